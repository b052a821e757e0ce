"""FE readings of the paper's ambiguous beam-on-disc geometry, and the claims checked under each.

The claim rows of Sections 9-12 name the default reading's datasets; for another reading the same rows are
evaluated on the same runs in that reading, looked up in the catalogue (``stickslip.catalogue``: the entry
of the row's path, then the entry with the same names but the other reading). Datasets that are not a
scene under a reading (sweeps, studies, the continuum runs) are shared by all readings and stay as they are.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping

from ..catalogue import Entry, same_entry
from .evaluate import ClaimResult, evaluate
from .rows import Claim


def in_reading(path: str, reading: str, entries: Mapping[str, Entry]) -> str:
    """The same run as ``path`` in FE reading ``reading``: ``path`` itself when its run has no reading."""
    entry = entries.get(path)
    if entry is None or "reading" not in dict(entry.names):
        return path
    other = same_entry(entries, entry, reading=reading)
    if other is None:
        raise KeyError(f"{path}: no {entry.kind} entry in FE reading {reading!r} in the catalogue")
    return other.path


def repoint(claim: Claim, reading: str, entries: Mapping[str, Entry]) -> Claim:
    """A copy of ``claim`` reading, for every dataset it names, the same run in FE reading ``reading``."""

    def moved(ref):
        if ref is None or ref.dataset is None:
            return ref
        return ref.model_copy(update={"dataset": in_reading(ref.dataset, reading, entries)})

    return moved(claim).model_copy(update={"lhs": moved(claim.lhs), "rhs": moved(claim.rhs)})


def claims_per_reading(
    claims: Iterable[Claim], readings: Iterable[str], entries: Mapping[str, Entry], open_dataset: Callable
) -> list[ClaimResult]:
    """Evaluate every claim once per FE reading; ``reading`` of each result is the FE reading's name.
    ``entries``: the catalogue's FE scene entries (``stickslip.catalogue.fe_scene_entries``).

    ``expected`` / ``note`` given per reading (a mapping with the FE reading names, and ``default`` for the
    main claims table, which evaluates the rows with reading "") are picked per reading."""
    claims = list(claims)
    return [evaluate(repoint(c, r, entries), r, open_dataset) for r in readings for c in claims]
