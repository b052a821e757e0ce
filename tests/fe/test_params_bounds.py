"""Each FE parameter key and its bound are declared once (stickslip.fe.params, ``declared``): the dataclass
checks it at construction and the config's typed section is generated from it, so the two refuse the same
values and name the same key."""

import math

import pytest
from pydantic import ValidationError

from stickslip.fe.params import BeamParams, Bound, ContactParams, DiscParams, SolverParams, bounds
from stickslip.schema.fe import Beam, Contact, Disc, FeSolver

PAIRS = [(BeamParams, Beam), (DiscParams, Disc), (ContactParams, Contact), (SolverParams, FeSolver)]
VALID = {DiscParams: {"speed_rev_per_min": 15.2}}


def outside(bound: Bound):
    """A value just outside the bound (NaN for an unbounded number)."""
    if bound.kind == "choice":
        return "no_such_choice"
    if bound.kind == "flag":
        return "yes"
    if bound.kind == "integer":
        return int(bound.ge) - 1
    for key, step in (("gt", 0.0), ("ge", -1e-9), ("lt", 0.0), ("le", 1e-9)):
        limit = getattr(bound, key)
        if limit is not None:
            return limit + (step if key in ("gt", "lt") else step * max(1.0, abs(limit)))
    return math.nan


def test_the_typed_sections_hold_the_declared_keys_in_order():
    for params, section in PAIRS:
        assert list(section.model_fields) == list(bounds(params))


@pytest.mark.parametrize(
    "params,section,key",
    [(p, s, k) for p, s in PAIRS for k in bounds(p)],
    ids=lambda v: v if isinstance(v, str) else None,
)
def test_the_dataclass_and_the_config_refuse_the_same_value(params, section, key):
    bad = outside(bounds(params)[key])
    with pytest.raises(ValueError, match=key):
        params(**{**VALID.get(params, {}), key: bad})
    with pytest.raises(ValidationError, match=key):
        section.model_validate({key: bad})
