"""Each FE parameter key and its bound are declared once (stickslip.fe.params, a pydantic model per
section): the config's typed section is generated from the same fields, so the two refuse the same values
and name the same key."""

import math

import pytest
from pydantic import ValidationError

from stickslip.fe.params import BeamParams, ContactParams, DiscParams, SolverParams
from stickslip.schema.fe import Beam, Contact, Disc, FeSolver

PAIRS = [(BeamParams, Beam), (DiscParams, Disc), (ContactParams, Contact), (SolverParams, FeSolver)]
VALID = {DiscParams: {"speed_rev_per_min": 15.2}}


def outside(params, key):
    """A value just outside the key's bound, read from the model's JSON schema (NaN for an unbounded
    number)."""
    schema = params.model_json_schema()["properties"][key]
    schema = next((s for s in schema.get("anyOf", [schema]) if s.get("type") != "null"), schema)
    if "enum" in schema or "const" in schema:
        return "no_such_choice"
    if schema["type"] == "boolean":
        return "yes"
    if schema["type"] == "integer":
        return schema["minimum"] - 1
    for key, step in (
        ("exclusiveMinimum", 0.0),
        ("minimum", -1e-9),
        ("exclusiveMaximum", 0.0),
        ("maximum", 1e-9),
    ):
        if key in schema:
            limit = schema[key]
            return limit + (step * max(1.0, abs(limit)) if step else 0.0)
    return math.nan


def test_the_typed_sections_hold_the_declared_keys_in_order():
    for params, section in PAIRS:
        assert list(section.model_fields) == list(params.model_fields)


@pytest.mark.parametrize(
    "params,section,key",
    [(p, s, k) for p, s in PAIRS for k in p.model_fields],
    ids=lambda v: v if isinstance(v, str) else None,
)
def test_the_model_and_the_config_refuse_the_same_value(params, section, key):
    bad = outside(params, key)
    with pytest.raises(ValueError, match=f"^{key}: "):
        params(**{**VALID.get(params, {}), key: bad})
    with pytest.raises(ValidationError, match=key):
        section.model_validate({key: bad})
