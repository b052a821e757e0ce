"""A paper figure's verdict from its claims: under the primary reading fixed by a rule, under the
equations as printed, and (labelled as a search) in the best of every reading.

The claims table (``results/claims/deviations.csv``) decides every claim once per reading. A figure's verdict
says how much: ``k of n`` decided claims reproduced, and a label from that fraction by a fixed rule
(:data:`VERDICT_RULE`). Only rows of the ``evidence`` class count (``stickslip.claims.rows``): a row that
cannot fail, reads the paper against its own words, checks a fitted setup or checks the project's own model
(not a number of the paper) is listed apart, never counted.

Which reading a verdict is given in is fixed by a rule, not by its score (``docs/READINGS.md``,
``config.yaml`` ``claims.primary_reading`` and ``claims.as_printed_reading``; for the beam-on-disc half the
first FE reading); the best-of-readings verdict is a search over N readings and is always labelled so.
Every consumer (the page, the notebooks) reads the one table :func:`figure_table` writes,
``results/claims/figure_verdicts.csv``.
"""

from __future__ import annotations

from dataclasses import dataclass

from .load import DISC_SPEEDS, disc_speed
from .rows import STATUSES, Claim

#: Figure verdicts, best first.
VERDICTS = ("reproduced", "mostly reproduced", "partly", "deviating", "not comparable")

#: Labels that read as success: each needs at least a third of the decided claims reproduced.
SUCCESS = ("reproduced", "mostly reproduced", "partly")

#: Claim statuses that decide a claim (``indistinguishable`` and ``not-comparable`` decide nothing).
DECIDED = ("reproduced", "deviates")

#: The rule of :func:`verdict_label` on k reproduced of n decided evidence claims, as the page states it.
VERDICT_RULE = {
    "reproduced": "every decided claim reproduced (k = n)",
    "mostly reproduced": "at least two thirds of the decided claims reproduced (k/n ≥ 2/3)",
    "partly": "at least a third reproduced (1/3 ≤ k/n < 2/3)",
    "deviating": "fewer than a third reproduced (k/n < 1/3)",
    "not comparable": "no claim decided (n = 0: none, or all undecided or not comparable)",
}

#: The column of :func:`figure_row` that holds a beam-on-disc figure's ``k of n`` at each disc speed.
SPEED_COLUMNS = {"15p2rpm": "stated_speed", "0p5mm_s": "implied_speed"}


def verdict_label(reproduced: int, decided: int) -> str:
    """The label of ``reproduced`` of ``decided`` claims (:data:`VERDICT_RULE`)."""
    if decided == 0:
        return "not comparable"
    share = reproduced / decided
    if reproduced == decided:
        return "reproduced"
    if share >= 2 / 3:
        return "mostly reproduced"
    return "partly" if share >= 1 / 3 else "deviating"


def is_evidence(row: dict) -> bool:
    return row.get("evidence", "evidence") == "evidence"


@dataclass(frozen=True)
class Tally:
    """k reproduced of n decided evidence claims, the claims left undecided (within the run's noise), those
    not comparable (nothing computed, the paper contradicting itself, a model not adequate), and the rows
    set apart."""

    reproduced: int
    decided: int
    undecided: int
    apart: int  #: rows that are not evidence (by construction, relabel, fit, model check)
    not_comparable: int = 0

    @property
    def label(self) -> str:
        return verdict_label(self.reproduced, self.decided)

    @property
    def text(self) -> str:
        return f"{self.reproduced} of {self.decided}"


def tally(rows: list[dict]) -> Tally:
    """The tally of claims-table rows (one reading's, or reading-independent ones)."""
    evidence = [r for r in rows if is_evidence(r)]
    statuses = [r["status"] for r in evidence]
    decided = sum(s in DECIDED for s in statuses)
    undecided = statuses.count("indistinguishable")
    apart = len(rows) - len(evidence)
    return Tally(statuses.count("reproduced"), decided, undecided, apart, statuses.count("not-comparable"))


def figure_verdict(statuses) -> str:
    """The label of a list of claim statuses (all taken as evidence)."""
    statuses = list(statuses)
    return verdict_label(statuses.count("reproduced"), sum(s in DECIDED for s in statuses))


def rows_in_reading(rows: list[dict], reading: str) -> list[dict]:
    """The claims-table rows of ``reading`` and the rows that hold in every reading (reading ``""``)."""
    return [r for r in rows if r["reading"] in ("", reading)]


def reading_key(rows: list[dict], reading: str, rank: int = 0) -> tuple:
    """Sort key of a reading for a figure's claims ``rows`` (smallest first): most reproduced evidence, then
    the largest reproduced share of the decided claims, then the most decided claims, then ``rank``."""
    t = tally(rows_in_reading(rows, reading))
    share = t.reproduced / t.decided if t.decided else 0.0
    return (-t.reproduced, -share, -t.decided, rank, reading)


def readings_by_preference(rows: list[dict], order: list[str]) -> list[str]:
    """The readings of ``rows``, best first (:func:`reading_key`; ties follow ``order``)."""
    rank = {name: i for i, name in enumerate(order)}
    readings = sorted({r["reading"] for r in rows} - {""})
    return sorted(readings, key=lambda rd: reading_key(rows, rd, rank.get(rd, len(rank))))


def best_reading(rows: list[dict], order: list[str]) -> str:
    """The first of :func:`readings_by_preference`; ``""`` when no row depends on a reading."""
    readings = readings_by_preference(rows, order)
    return readings[0] if readings else ""


def status_counts(statuses) -> dict[str, int]:
    """Count of each claim status (every status of the claims table, zeros included)."""
    statuses = list(statuses)
    return {s: statuses.count(s) for s in STATUSES}


def speed_of(claim: Claim | None) -> str:
    """The disc speed a beam-on-disc claim reads (a key of :data:`DISC_SPEEDS`), ``""`` for none or both
    (or no claim: a table row whose id is in no claims file)."""
    return "" if claim is None else disc_speed(claim)


def _columns(prefix: str, t: Tally | None, reading: str) -> dict:
    if t is None:
        names = ("reading", "verdict", "reproduced", "decided", "undecided", "not_comparable")
        return {f"{prefix}_{name}": "" for name in names}
    return {
        f"{prefix}_reading": reading,
        f"{prefix}_verdict": t.label,
        f"{prefix}_reproduced": t.reproduced,
        f"{prefix}_decided": t.decided,
        f"{prefix}_undecided": t.undecided,
        f"{prefix}_not_comparable": t.not_comparable,
    }


def figure_row(
    key: str,
    half: str,
    rows: list[dict],
    claims: dict[str, Claim],
    primary: str,
    printed: str,
    order: list[str],
    fe_rows: list[dict] | None = None,
    alternative: str = "",
) -> dict:
    """One figure's verdicts. 1-DOF: under ``primary``, under ``printed``, under the primary rule's
    ``alternative`` application (if any) and in the best of its readings (a search). Beam-on-disc
    (``fe_rows``: the claims under every FE reading, ``primary`` the FE reading the claims table checks):
    under the primary reading at each disc speed, ``printed`` = the stated speed alone,
    the search over the FE readings."""
    apart: dict[str, int] = {}  # rows set apart, counted once (in the primary reading, if they have one)
    for r in rows if fe_rows is not None else rows_in_reading(rows, primary):
        if not is_evidence(r):
            claim = claims.get(r["claim"])
            cls = r.get("evidence", "") if claim is None else claim.evidence
            apart[cls] = apart.get(cls, 0) + 1
    out = {"figure": key, "half": half}
    if fe_rows is None:
        best = best_reading(rows, order)
        readings = sorted({r["reading"] for r in rows} - {""})
        out |= _columns("primary", tally(rows_in_reading(rows, primary)), primary)
        out |= _columns("printed", tally(rows_in_reading(rows, printed)), printed)
        alt = tally(rows_in_reading(rows, alternative)) if alternative else None
        out |= _columns("alternative", alt, alternative)
        out |= _columns("best", tally(rows_in_reading(rows, best)) if best else None, best)
        out["readings_searched"] = len(readings)
        out |= dict.fromkeys(SPEED_COLUMNS.values(), "")
    else:
        by_speed = {s: [r for r in rows if speed_of(claims.get(r["claim"])) in ("", s)] for s in DISC_SPEEDS}
        out |= _columns("primary", tally(rows), primary)
        stated = tally(by_speed["15p2rpm"])
        out |= _columns("printed", stated, f"{primary} at 15.2 rev/min")
        out |= _columns("alternative", None, "")
        ids = {r["claim"] for r in rows}
        mine = [r for r in fe_rows if r["claim"] in ids]
        readings = list(dict.fromkeys(r["reading"] for r in mine))
        best = min(
            readings,
            key=lambda rd: reading_key(mine, rd, readings.index(rd)),
            default="",
        )
        out |= _columns("best", tally([r for r in mine if r["reading"] == best]) if best else None, best)
        out["readings_searched"] = len(readings)
        out |= {column: tally(by_speed[speed]).text for speed, column in SPEED_COLUMNS.items()}
    out["not_evidence"] = ", ".join(f"{n} {cls.replace('_', ' ')}" for cls, n in sorted(apart.items()))
    return out


def figure_table(
    paper: dict,
    rows: list[dict],
    claims: list[Claim],
    primary: str,
    printed: str,
    fe_primary: str,
    fe_rows: list[dict],
    order: list[str],
    alternative: str = "",
) -> list[dict]:
    """Every entry of the paper's figure list (``paper.yaml``: figures, then text-only sections) with its
    verdicts (:func:`figure_row`). ``rows``: the claims table; ``fe_rows``: the FE readings table;
    ``order``: the readings as the interpretation study ranks them (``studies.ranking``), which breaks ties
    between equally good readings."""
    by_id = {c.id: c for c in claims}
    figs_of = {c.id: sorted(c.figures) for c in claims}
    out = []
    for entry in paper["figures"] + paper.get("text", []):
        number = entry.get("number")
        if number is not None:
            mine = [r for r in rows if number in figs_of.get(r["claim"], [])]
            key = str(number)
        else:
            mine = [
                r
                for r in rows
                if not figs_of.get(r["claim"])
                and r["claim"] in by_id
                and by_id[r["claim"]].section == entry["section"]
            ]
            key = entry["key"]
        fe = entry.get("half") == "fe"
        out.append(
            figure_row(
                key,
                entry.get("half", "text"),
                mine,
                by_id,
                fe_primary if fe else primary,
                printed,
                order,
                fe_rows if fe else None,
                "" if fe else alternative,
            )
        )
    return out
