"""The methods-study config validates against its schema and every listed setting builds a solver."""

from pathlib import Path

import jsonschema
import pytest
import yaml

from stickslip.solvers import make_solver
from stickslip.studies import methods as methods_study

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("path", ["config/methods.yaml", "config/test/methods.yaml"])
def test_config_validates_and_builds(path):
    cfg = yaml.safe_load((ROOT / path).read_text())
    schema = yaml.safe_load((ROOT / "workflow/schemas/methods.schema.yaml").read_text())
    jsonschema.validate(cfg, schema)
    study = cfg["methods_study"]
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


def test_schema_rejects_unknown_solver():
    schema = yaml.safe_load((ROOT / "workflow/schemas/methods.schema.yaml").read_text())
    cfg = yaml.safe_load((ROOT / "config/test/methods.yaml").read_text())
    cfg["methods_study"]["methods"].append({"solver": "euler"})
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(cfg, schema)
