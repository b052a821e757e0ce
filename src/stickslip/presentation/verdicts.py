"""A paper figure's verdict from the statuses of its claims, and the reading each figure is judged in.

The claims table (``results/claims/deviations.csv``) decides every claim once per reading. A figure is judged
in one reading, its *best*: the reading in which most of its claims are reproduced, then the largest share of
its decided claims, then the most decided claims (a reading that measures something beats one that measures
nothing), then the order of the overall reading ranking. Claims that do not depend on a reading count in every
reading.
"""

from __future__ import annotations

#: Figure verdicts, best first.
VERDICTS = ("reproduced", "partly", "deviating", "not comparable")

#: Claim statuses that decide a claim (``indistinguishable`` and ``not-comparable`` decide nothing).
DECIDED = ("reproduced", "deviates")

#: The rule of :func:`figure_verdict`, as the page states it.
VERDICT_RULE = {
    "reproduced": "every decided claim of the figure is reproduced in its best reading",
    "partly": "some decided claims are reproduced in the best reading, some deviate",
    "deviating": "no decided claim is reproduced in the best reading",
    "not comparable": "no claim of the figure is decided (none, or all indistinguishable or not comparable)",
}


def fitted_claims(claims: list[dict]) -> set[str]:
    """Ids of the claims that check a setup fitted to the paper's numbers (``fit: true``): shown beside a
    figure's forward verdict, never counted in it."""
    return {c["id"] for c in claims if c.get("fit")}


def figure_verdict(statuses) -> str:
    """``reproduced`` if every decided status is reproduced, ``partly`` if some are, ``deviating`` if none
    is, ``not comparable`` if no status is decided. ``statuses`` are claim statuses of one reading."""
    decided = [s for s in statuses if s in DECIDED]
    if not decided:
        return "not comparable"
    reproduced = sum(s == "reproduced" for s in decided)
    if reproduced == len(decided):
        return "reproduced"
    return "partly" if reproduced else "deviating"


def rows_in_reading(rows: list[dict], reading: str) -> list[dict]:
    """The claims-table rows of ``reading`` and the rows that hold in every reading (reading ``""``)."""
    return [r for r in rows if r["reading"] in ("", reading)]


def reading_key(rows: list[dict], reading: str, rank: int = 0) -> tuple:
    """Sort key of a reading for a figure's claims ``rows`` (smallest first): most reproduced, then the
    largest reproduced share of the decided claims, then the most decided claims, then ``rank``."""
    statuses = [r["status"] for r in rows_in_reading(rows, reading)]
    reproduced = statuses.count("reproduced")
    decided = sum(s in DECIDED for s in statuses)
    return (-reproduced, -(reproduced / decided if decided else 0.0), -decided, rank, reading)


def readings_by_preference(rows: list[dict], order: list[str]) -> list[str]:
    """The readings of ``rows``, best first (:func:`reading_key`; ties follow ``order``, the overall
    ranking)."""
    rank = {name: i for i, name in enumerate(order)}
    readings = sorted({r["reading"] for r in rows} - {""})
    return sorted(readings, key=lambda rd: reading_key(rows, rd, rank.get(rd, len(rank))))


def best_reading(rows: list[dict], order: list[str]) -> str:
    """The first of :func:`readings_by_preference`; ``""`` when no row depends on a reading."""
    readings = readings_by_preference(rows, order)
    return readings[0] if readings else ""


def status_counts(statuses) -> dict[str, int]:
    """Count of each claim status (every status of the claims table, zeros included)."""
    from ..io.claims import STATUSES

    statuses = list(statuses)
    return {s: statuses.count(s) for s in STATUSES}
