"""The methods-study config validates against its typed model and every listed setting builds a solver."""

from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from stickslip.pipeline.config import load_config
from stickslip.schema import MethodsStudy, StudyMethod
from stickslip.solvers import make_solver
from stickslip.studies import methods as methods_study

ROOT = Path(__file__).resolve().parents[2]


def study_mapping(*overrides) -> dict:
    return load_config([ROOT / "config/methods.yaml", *(ROOT / p for p in overrides)])["methods_study"]


def study_config(*overrides) -> MethodsStudy:
    return MethodsStudy.model_validate(study_mapping(*overrides))


@pytest.mark.parametrize("overrides", [(), ("config/test/methods.yaml",)], ids=["default", "small"])
def test_config_validates_and_builds(overrides):
    study = study_config(*overrides)
    for entries in (study.methods, study.failure_map.methods):
        for name, settings, label in methods_study.expand_methods(entries):
            make_solver(name, **settings)
            assert label.startswith(name)
    for scene in study.scenes:
        methods_study.scene_model(study, scene)


def test_atol_follows_rtol_and_labels_name_every_setting():
    entry = StudyMethod(
        solver="sign_rk", settings={"method": "RK45"}, atol_per_rtol=1e-3, sweep={"rtol": [1e-2, 1e-4]}
    )
    runs = methods_study.expand_methods([entry, StudyMethod(solver="exact")])
    assert [s.get("atol") for _, s, _ in runs] == pytest.approx([1e-5, 1e-7, None])
    labels = [label for *_, label in runs]
    assert labels[0] == "sign_rk[method=RK45,rtol=0.01,atol=1e-05]" and labels[2] == "exact"


def test_atol_per_rtol_without_an_rtol_is_refused_naming_the_key():
    with pytest.raises(ValidationError, match="atol_per_rtol: needs an rtol"):
        StudyMethod(solver="sign_rk", atol_per_rtol=1e-3, sweep={"method": ["RK45"]})


def test_model_rejects_unknown_solver_naming_the_entry():
    study = study_mapping("config/test/methods.yaml")
    study["methods"].append({"solver": "euler"})
    with pytest.raises(ValidationError) as info:
        MethodsStudy.model_validate(study)
    assert ("methods", len(study["methods"]) - 1, "solver") in [e["loc"] for e in info.value.errors()]


def test_failure_map_runs_each_method_once_and_the_work_precision_study_repeats_short_runs():
    study = study_mapping("config/test/methods.yaml")
    study["failure_map"]["values"] = study["failure_map"]["values"][:1]
    study["failure_map"]["t_end"] = 2.0
    fmap = methods_study.failure_map_dataset(MethodsStudy.model_validate(study))
    assert set(np.unique(fmap["repeats"].values)) == {1}
    assert "each run once" in fmap.attrs["timing"]
    default = study_config()  # the full study times a short run at least min_repeats (3) times
    model = methods_study.scene_model(default, default.failure_map.scene)
    methods = methods_study.expand_methods([StudyMethod(solver="karnopp", settings={"eta": 1e-2})])
    records, *_ = methods_study.run_scene(default, model, 2.0, methods, paper=False)
    assert records[0]["repeats"] >= default.timing.min_repeats > 1


def test_the_papers_method_is_run_once_when_it_is_one_of_the_listed_settings(monkeypatch):
    study = study_config("config/test/methods.yaml")
    model = methods_study.scene_model(study, "baseline_sigma05")
    calls = []
    real = methods_study.measure_run
    monkeypatch.setattr(
        methods_study, "measure_run", lambda solver, *a, **k: calls.append(solver) or real(solver, *a, **k)
    )
    listed = methods_study.expand_methods(study.methods)
    records, _, _, paper = methods_study.run_scene(study, model, 2.0, listed)
    assert len(calls) == len(listed)  # the paper's settings (sign_rk RK45, rtol 1e-3) are among them
    (same,) = [r for r in records if r["label"] == "sign_rk[method=RK45,rtol=0.001,atol=1e-06]"]
    assert paper is same
    others = [m for m in listed if not (m[0] == "sign_rk" and m[1].get("rtol") == 1e-3)]
    calls.clear()
    _, _, _, paper = methods_study.run_scene(study, model, 2.0, others)
    assert len(calls) == len(others) + 1 and paper["rhs_evaluations"] == same["rhs_evaluations"]
