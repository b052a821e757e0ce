"""The interpretation study: rank the readings of the paper by how many claim checks they reproduce."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..claims.rows import STATUSES
from ..claims.verdicts import is_evidence, status_counts

#: Columns of the ranking table, in order (one count column per status).
COLUMNS = ("reading", *STATUSES, "total", "reproduced_fraction_of_comparable")


def rank_readings(rows: list[dict], readings: list[str]) -> list[dict]:
    """Per reading: counts of each status of ``STATUSES`` over the per-reading claim rows, best first (most
    reproduced, then fewest deviations). The fraction is reproduced / (reproduced + deviates): an
    indistinguishable check is decided neither way and is not comparable to the paper's number."""
    table = []
    for r in readings:  # only rows that could have failed count (stickslip.claims.rows.EVIDENCE_CLASSES)
        mine = [row for row in rows if row["reading"] == r and is_evidence(row)]
        counts = status_counts(row["status"] for row in mine)
        comparable = counts["reproduced"] + counts["deviates"]
        table.append(
            {
                "reading": r,
                **counts,
                "total": len(mine),
                "reproduced_fraction_of_comparable": counts["reproduced"] / comparable if comparable else 0.0,
            }
        )
    return sorted(table, key=lambda t: (-t["reproduced"], t["deviates"], t["reading"]))


def unreproduced_claims(rows: list[dict], readings: list[str]) -> list[dict]:
    """Claims that no reading reproduces (reading-independent rows included), with every reading's reason."""
    by_claim: dict[str, list[dict]] = {}
    for row in rows:
        if row["reading"] in readings or row["reading"] == "":
            by_claim.setdefault(row["claim"], []).append(row)
    out = []
    for claim, mine in by_claim.items():
        if any(r["status"] == "reproduced" for r in mine):
            continue
        statuses = "; ".join(f"{r['reading'] or '-'}: {r['status']}" for r in mine)
        # the longest reason, ties broken by the text: a set has no order of its own (hash seed)
        reasons = sorted(
            {r["reason"].split("; ", 1)[-1] for r in mine if r["reason"]}, key=lambda text: (len(text), text)
        )
        out.append(
            {
                "claim": claim,
                "figure": mine[0]["figure"],
                "statuses": statuses,
                "why": reasons[-1] if reasons else "",
                "quote": mine[0]["quote"],
            }
        )
    return out


def reading_dataset(readings: list[str], long_name: str, variables: dict) -> xr.Dataset:
    """A table with one row per reading as a dataset: ``variables`` name -> (values, attrs) along
    ``reading``, the readings' names (``long_name``) an auxiliary coordinate: CF wants dimension coordinates
    numeric and monotonic."""
    names = ("reading", np.array(readings, dtype=object), {"long_name": long_name})
    return xr.Dataset({k: ("reading", *v) for k, v in variables.items()}, coords={"reading_name": names})
