"""Claims rows for the tests, built as the loader hands them on (typed, checked: a row no claims file could
hold is an error here too)."""

from stickslip.claims.rows import Claim

ROW = {
    "id": "f",
    "section": "3",
    "figure": "Fig. 2",
    "figures": [2],
    "quote": "q",
    "kind": "value",
    "dataset": "r/{reading}.nc",
    "variable": "f",
    "value": 0.25,
    "unit": "Hz",
    "tolerance": {"rel": 0.2, "reason": "test"},
    "expected": "reproduced",
    "evidence": "evidence",
}
#: keys of ROW that only a value (or ratio) row holds: a compare or trend row built from ROW drops them
VALUE_ONLY = {"value": None, "tolerance": None}


def claim(**changes) -> Claim:
    """ROW with ``changes`` as the loader hands it on (checked: a row no claims file could hold is an error
    here too); a key changed to None is left out."""
    row = {k: v for k, v in {**ROW, **changes}.items() if v is not None}
    return Claim.model_validate(row)


def compare(lhs, rhs, relation=">", **changes) -> Claim:
    """A comparison built from ROW: ``lhs`` and ``rhs`` as a claims file spells them."""
    return claim(kind="compare", lhs=lhs, rhs=rhs, relation=relation, **VALUE_ONLY, **changes)


def trend(**changes) -> Claim:
    return claim(kind="trend", **VALUE_ONLY, **changes)
