"""The methods-study config validates against its typed model and every listed setting builds a solver."""

from pathlib import Path

import pytest
from pydantic import ValidationError

from stickslip.config import load_config
from stickslip.config_models import MethodsStudy
from stickslip.solvers import make_solver
from stickslip.studies import methods as methods_study

ROOT = Path(__file__).resolve().parents[2]


def study_config(*overrides):
    return load_config([ROOT / "config/methods.yaml", *(ROOT / p for p in overrides)])["methods_study"]


@pytest.mark.parametrize("overrides", [(), ("config/test/methods.yaml",)], ids=["default", "small"])
def test_config_validates_and_builds(overrides):
    study = study_config(*overrides)
    MethodsStudy.model_validate(study)
    for entries in (study["methods"], study["failure_map"]["methods"]):
        for name, settings, label in methods_study.expand_methods(entries):
            make_solver(name, **settings)
            assert label.startswith(name)
    for scene in study["scenes"]:
        methods_study.scene_model(study, scene)


def test_atol_follows_rtol():
    runs = methods_study.expand_methods(
        [{"solver": "sign_rk", "atol_per_rtol": 1e-3, "sweep": {"rtol": [1e-2, 1e-4]}}]
    )
    assert [s["atol"] for _, s, _ in runs] == pytest.approx([1e-5, 1e-7])


def test_model_rejects_unknown_solver_naming_the_entry():
    study = study_config("config/test/methods.yaml")
    study["methods"].append({"solver": "euler"})
    with pytest.raises(ValidationError) as info:
        MethodsStudy.model_validate(study)
    assert ("methods", len(study["methods"]) - 1, "solver") in [e["loc"] for e in info.value.errors()]
