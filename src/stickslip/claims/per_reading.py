"""FE readings of the paper's ambiguous beam-on-disc geometry, and the claims checked under each.

The claim rows of Sections 9-12 name the default reading's datasets (``results/fe/<default>/...``); for
another reading the same rows are evaluated with those paths pointed at ``results/fe/<reading>/...``.
Datasets outside a reading folder (sweeps, studies, the continuum increments) are shared by all readings.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterable

from .evaluate import ClaimResult, evaluate


def repoint(claim: dict, default: str, reading: str) -> dict:
    """A copy of ``claim`` with every dataset path under ``results/fe/<default>/`` moved to ``<reading>``."""
    c = copy.deepcopy(claim)
    old, new = f"results/fe/{default}/", f"results/fe/{reading}/"
    for ref in [c, c.get("lhs"), c.get("rhs")]:
        if isinstance(ref, dict) and isinstance(ref.get("dataset"), str):
            ref["dataset"] = ref["dataset"].replace(old, new)
    return c


def claims_per_reading(
    claims: Iterable[dict], readings: Iterable[str], default: str, open_dataset: Callable
) -> list[ClaimResult]:
    """Evaluate every claim once per FE reading; ``reading`` of each result is the FE reading's name.

    ``expected`` / ``note`` given per reading (a mapping with the FE reading names, and ``default`` for the
    main claims table, which evaluates the rows with reading "") are picked per reading."""
    return [evaluate(repoint(c, default, r), r, open_dataset) for r in readings for c in claims]
