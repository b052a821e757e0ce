"""The claims table: every number and directional statement of the paper, checked against the datasets.

A claim row (``config/claims/*.yaml``) names a dataset and a scalar variable in it. ``{reading}`` in a
dataset path makes the claim be checked once per reading of the paper's equations. Kinds:

``value``    measured variable vs the reported number within a tolerance
``ratio``    lhs / rhs vs the reported number within a tolerance
``compare``  lhs <relation> rhs
``trend``    sign of the least-squares slope of ``variable`` along ``coord`` of a sweep dataset; ``sign: 0``
             claims "no effect"; ``coord_scale: log`` fits against log10(coord). A change below
             ``min_relative_change`` (default TREND_FLOOR) is no trend.

Status is ``reproduced``, ``deviates`` or ``not-comparable`` (nothing measurable, or the paper contradicts
itself: rows with ``comparable: false``). ``expected`` pins the status (one string, or one per reading);
the check fails when a measured status differs from the pinned one, so every change is deliberate.
"""

from __future__ import annotations

import csv
import math
import operator
import sys
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import yaml

STATUSES = ("reproduced", "deviates", "not-comparable")
KINDS = ("value", "ratio", "compare", "trend")
RELATIONS = {">": operator.gt, "<": operator.lt, ">=": operator.ge, "<=": operator.le}
REQUIRED = {"id", "section", "figure", "quote", "kind", "expected"}


#: A fitted change smaller than this fraction of the mean |value| over the swept range counts as no trend
#: (a directional sentence is about a visible effect, not about round-off).
TREND_FLOOR = 0.05


def relative_change(slope: float, x: np.ndarray, y: np.ndarray) -> float:
    """Fitted change over the coordinate range, relative to the mean magnitude of the variable."""
    scale = float(np.mean(np.abs(y)))
    return slope * float(np.ptp(x)) / scale if scale > 0 else (0.0 if slope == 0 else np.sign(slope) * np.inf)


class ClaimsError(ValueError):
    """A claims file is malformed; the message names the file, the claim and the key."""


@dataclass
class ClaimResult:
    claim: str
    reading: str
    section: str
    figure: str
    kind: str
    quantity: str
    reported: float
    unit: str
    measured: float
    deviation: float
    status: str
    expected: str
    matches_expected: bool
    reason: str
    quote: str


def load_claims(paths) -> list[dict]:
    claims, seen = [], {}
    for path in sorted(Path(p) for p in paths):
        rows = yaml.safe_load(path.read_text()) or []
        if not isinstance(rows, list):
            raise ClaimsError(f"{path}: expected a list of claim rows")
        for i, row in enumerate(rows):
            where = f"{path}: row {i} ({row.get('id', '?') if isinstance(row, dict) else '?'})"
            if not isinstance(row, dict):
                raise ClaimsError(f"{where}: expected a mapping")
            missing = sorted(REQUIRED - set(row))
            if missing:
                raise ClaimsError(f"{where}: missing key {missing[0]!r}")
            if row["kind"] not in KINDS:
                raise ClaimsError(f"{where}: kind {row['kind']!r} is not one of {KINDS}")
            if row["id"] in seen:
                raise ClaimsError(f"{where}: id {row['id']!r} already used in {seen[row['id']]}")
            seen[row["id"]] = path
            _check_expected(row, where)
            claims.append({**row, "_file": str(path)})
    return claims


def _check_expected(row, where):
    exp = row["expected"]
    values = exp.values() if isinstance(exp, dict) else [exp]
    for v in values:
        if v not in STATUSES:
            raise ClaimsError(f"{where}: expected status {v!r} is not one of {STATUSES}")


def dataset_paths(claim: dict) -> list[str]:
    refs = [claim] + [claim[k] for k in ("lhs", "rhs") if isinstance(claim.get(k), dict)]
    return [r["dataset"] for r in refs if "dataset" in r]


def readings_of(claim: dict, readings: list[str]) -> list[str]:
    return list(readings) if any("{reading}" in p for p in dataset_paths(claim)) else [""]


def required_datasets(claims: list[dict], readings: list[str]) -> list[str]:
    out = set()
    for c in claims:
        for r in readings_of(c, readings):
            out.update(p.format(reading=r) for p in dataset_paths(c))
    return sorted(out)


def _scalar(open_dataset: Callable, ref: dict, reading: str) -> float:
    """A dataset's scalar variable, or a constant given as ``{value: number}``."""
    if "value" in ref and "dataset" not in ref:
        return float(ref["value"])
    ds = open_dataset(ref["dataset"].format(reading=reading))
    if ref["variable"] not in ds:
        return float("nan")
    return float(np.asarray(ds[ref["variable"]].values).reshape(-1)[0])


def solver_failures(opened: list) -> list[str]:
    """Messages of the failed solver runs among the (path, dataset) pairs a claim read."""
    out = []
    for path, ds in opened:
        status = ds.variables.get("solver_status") if hasattr(ds, "variables") else None
        if status is not None and np.any(np.asarray(status.values) != 0):
            out.append(f"{path}: {status.attrs.get('message', 'no message')}")
    return out


def _name(ref: dict) -> str:
    return ref.get("variable", f"{ref.get('value')}")


def _per_reading(value, reading, default=""):
    if isinstance(value, dict):
        return value.get(reading, value.get("default", default))
    return default if value is None else value


def evaluate(claim: dict, reading: str, open_dataset: Callable) -> ClaimResult:
    opened: list = []  # every dataset this claim reads, to refuse numbers from a failed solver run

    def open_dataset(path, _open=open_dataset):
        ds = _open(path)
        opened.append((path, ds))
        return ds

    kind = claim["kind"]
    reported, measured, deviation = float("nan"), float("nan"), float("nan")
    unit = str(claim.get("unit", ""))
    quantity = str(claim.get("variable", ""))
    detail = ""
    holds = None
    if kind in ("value", "ratio"):
        reported = float(claim["value"])
        if kind == "value":
            measured = _scalar(open_dataset, claim, reading)
        else:
            lhs, rhs = (
                _scalar(open_dataset, claim["lhs"], reading),
                _scalar(open_dataset, claim["rhs"], reading),
            )
            measured = lhs / rhs if rhs != 0 else float("nan")
            quantity = f"{_name(claim['lhs'])} / {_name(claim['rhs'])}"
        if math.isfinite(measured):
            deviation = (measured - reported) / abs(reported) if reported != 0 else measured - reported
            tol = claim.get("tolerance", {})
            rel_ok = "rel" in tol and abs(deviation) <= float(tol["rel"])
            abs_ok = "abs" in tol and abs(measured - reported) <= float(tol["abs"])
            holds = rel_ok or abs_ok
            detail = f"measured {measured:.4g} vs reported {reported:.4g} ({100 * deviation:+.1f} %)"
    elif kind == "compare":
        lhs, rhs = _scalar(open_dataset, claim["lhs"], reading), _scalar(open_dataset, claim["rhs"], reading)
        measured, reported = lhs, rhs
        quantity = f"{_name(claim['lhs'])} {claim['relation']} {_name(claim['rhs'])}"
        if math.isfinite(lhs) and math.isfinite(rhs):
            holds = RELATIONS[claim["relation"]](lhs, rhs)
            detail = f"{lhs:.4g} {claim['relation']} {rhs:.4g} is {holds}"
    elif kind == "trend":
        ds = open_dataset(claim["dataset"].format(reading=reading))
        quantity = f"d {claim['variable']} / d {claim['coord']}"
        reported = float(claim["sign"])
        if claim["variable"] in ds and claim["coord"] in ds.variables:
            x = np.asarray(ds[claim["coord"]].values, dtype=float).reshape(-1)
            y = np.asarray(ds[claim["variable"]].values, dtype=float).reshape(-1)
            if claim.get("coord_scale") == "log":  # decade sweeps: the trend per decade
                x = np.log10(np.where(x > 0, x, np.nan))
            ok = np.isfinite(x) & np.isfinite(y)
            if ok.sum() >= 2 and np.ptp(x[ok]) > 0:
                measured = float(np.polyfit(x[ok], y[ok], 1)[0])
                change = relative_change(measured, x[ok], y[ok])
                floor = float(claim.get("min_relative_change", TREND_FLOOR))
                direction = 0.0 if abs(change) < floor else float(np.sign(measured))
                holds = direction == np.sign(reported)
                words = {1.0: "rising", -1.0: "falling", 0.0: "no trend"}[direction]
                detail = f"slope {measured:.4g}: {100 * change:+.1f} % of the mean over the range ({words})"
    failures = solver_failures(opened)
    if failures:  # a failed run measures nothing: never compare its numbers
        status = "not-comparable"
        detail = "solver failed (" + "; ".join(failures) + ")"
    elif claim.get("comparable", True) is False:
        status = "not-comparable"
    elif holds is None:
        status = "not-comparable"
        detail = detail or "not measurable in this reading (variable missing or NaN)"
    else:
        status = "reproduced" if holds else "deviates"
    note = _per_reading(claim.get("note"), reading)
    reason = "; ".join(s for s in (detail, note if status != "reproduced" else "") if s)
    expected = _per_reading(claim["expected"], reading, default="(not pinned)")
    return ClaimResult(
        claim=claim["id"],
        reading=reading,
        section=str(claim["section"]),
        figure=str(claim["figure"]),
        kind=kind,
        quantity=quantity,
        reported=reported,
        unit=unit,
        measured=measured,
        deviation=deviation,
        status=status,
        expected=expected,
        matches_expected=(status == expected),
        reason=reason,
        quote=" ".join(str(claim["quote"]).split()),
    )


def evaluate_all(claims: list[dict], readings: list[str], open_dataset: Callable) -> list[ClaimResult]:
    return [evaluate(c, r, open_dataset) for c in claims for r in readings_of(c, readings)]


FIELDS = [f for f in ClaimResult.__dataclass_fields__]


def write_table(results: list[ClaimResult], csv_path, md_path=None) -> None:
    """CSV (machine) and Markdown (human) deviations tables, each written atomically."""
    csv_path = Path(csv_path)
    csv_path.parent.mkdir(parents=True, exist_ok=True)
    tmp = csv_path.with_suffix(".csv.tmp")
    with tmp.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=FIELDS)
        writer.writeheader()
        for r in results:
            writer.writerow(asdict(r))
    tmp.replace(csv_path)
    if md_path:
        md_path = Path(md_path)
        lines = [
            "| claim | reading | figure | quantity | reported | measured | unit | status | expected "
            "| reason |",
            "|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in results:
            flag = "" if r.matches_expected else " **(changed)**"
            lines.append(
                f"| {r.claim} | {r.reading or '-'} | {r.figure} | {r.quantity} | {r.reported:.4g} | "
                f"{r.measured:.4g} | {r.unit} | {r.status}{flag} | {r.expected} | {r.reason} |"
            )
        tmp = md_path.with_suffix(".md.tmp")
        tmp.write_text("\n".join(lines) + "\n")
        tmp.replace(md_path)


def read_table(csv_path) -> list[dict]:
    with Path(csv_path).open(newline="") as fh:
        return list(csv.DictReader(fh))


def unexpected(rows: list[dict]) -> list[dict]:
    return [r for r in rows if str(r["matches_expected"]) != "True"]


def main(argv=None) -> int:
    """``python -m stickslip.io.claims check TABLE.csv``: exit 1 if any status differs from its pin."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2 or argv[0] != "check":
        print("usage: python -m stickslip.io.claims check results/claims/deviations.csv", file=sys.stderr)
        return 2
    rows = read_table(argv[1])
    bad = unexpected(rows)
    for r in bad:
        print(
            f"CHANGED {r['claim']} [{r['reading'] or '-'}]: measured status {r['status']}, "
            f"pinned {r['expected']} ({r['reason']})"
        )
    counts = {s: sum(r["status"] == s for r in rows) for s in STATUSES}
    print(
        f"{len(rows)} claim checks: "
        + ", ".join(f"{v} {k}" for k, v in counts.items())
        + f"; {len(bad)} differ from the pinned status"
    )
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
