"""The typed config layer: the repository's configs validate, the committed JSON schema is generated from the
models (never written twice), and the models reject what the hand-written schemas rejected."""

import math
from glob import glob

import pytest
from pydantic import ValidationError

from stickslip.pipeline.config import load_config
from stickslip.pipeline.config_models import SCHEMA_PATH, PipelineConfig, schema_text

from project_run import ROOT


def repository_config(test=False):
    files = sorted(glob(str(ROOT / "config" / "*.yaml")))
    return load_config(files + (sorted(glob(str(ROOT / "config" / "test" / "*.yaml"))) if test else []))


@pytest.mark.parametrize("test", [False, True], ids=["default", "small"])
def test_repository_configs_validate(test):
    PipelineConfig.model_validate(repository_config(test))


def test_committed_schema_is_the_generated_one():
    assert (ROOT / SCHEMA_PATH).read_text() == schema_text(), (
        "workflow/schemas/config.schema.json is stale: "
        "run `python -m stickslip.pipeline.config_models --write`"
    )


@pytest.mark.parametrize(
    "path, value",
    [
        (("onedof", "scenes", "fig02", "params", "mass"), math.nan),
        (("onedof", "scenes", "fig02", "params", "mass"), "1.0"),  # strict: no string for a number
        (("onedof", "scenes", "fig02", "params", "masss"), 1.0),  # unknown key
        (("fe", "defaults", "beam", "poisson_ratio"), 0.5),
        (("dense_map", "maps", "speed_damping", "axes"), []),
        (("methods_study", "failure_map", "methods", 0, "solver"), "rk99"),
        (("ensemble", "step_factor"), 1.0),
    ],
)
def test_bad_values_are_rejected_naming_the_full_key(path, value):
    config = repository_config()
    node = config
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    with pytest.raises(ValidationError) as info:
        PipelineConfig.model_validate(config)
    locations = [".".join(map(str, e["loc"])) for e in info.value.errors()]
    assert any(loc.startswith(".".join(map(str, path))) for loc in locations), locations


def test_typed_names_are_the_models_own():
    """The typed layer's readings, unit readings and freeable inverse parameters are the ones the code
    implements (written twice only because a Literal type needs the values spelled out)."""
    from typing import get_args

    from stickslip.inverse.problem import PARAMS
    from stickslip.model.friction import VARIANTS
    from stickslip.model.params import UNIT_READINGS
    from stickslip.pipeline.config_models import InverseParameter, Units, Variant

    assert get_args(Variant) == VARIANTS
    assert get_args(Units) == UNIT_READINGS
    assert get_args(InverseParameter) == PARAMS
