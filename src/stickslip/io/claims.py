"""The claims table: every number and directional statement of the paper, checked against the datasets.

A claim row (``config/claims/*.yaml``) names a dataset and a scalar variable in it. ``{reading}`` in a
dataset path makes the claim be checked once per reading of the paper's equations. Kinds:

``value``    measured variable vs the reported number within a tolerance
``ratio``    lhs / rhs vs the reported number within a tolerance
``compare``  lhs <relation> rhs
``trend``    sign of the least-squares slope of ``variable`` along ``coord`` of a sweep dataset; ``sign: 0``
             claims "no effect"; ``coord_scale: log`` fits against log10(coord). A change below
             ``min_relative_change`` (default TREND_FLOOR) is no trend.

Status is ``reproduced``, ``deviates``, ``indistinguishable`` or ``not-comparable`` (nothing measurable,
or the paper contradicts itself: rows with ``comparable: false``). Every claim reduces to a *decision
variable* on one side of a threshold (value/ratio: |measured - reported| against the tolerance band;
compare: lhs - rhs against 0; trend: the relative change against +-floor). ``margin`` is its distance to the
threshold, ``spread`` its range across the dataset's perturbation ensemble (``<variable>_ensemble``,
stickslip.ensemble). A margin below MARGIN_FACTOR spreads is ``indistinguishable``: the pipeline's own
numerical noise could flip it, so it is never called reproduced or deviating. ``expected`` pins the
status (one string, or one per reading); the check fails when a measured status differs from the pinned
one, so every change is deliberate.
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

STATUSES = ("reproduced", "deviates", "indistinguishable", "not-comparable")

#: A claim is decided only when its margin to the threshold exceeds this many ensemble spreads.
MARGIN_FACTOR = 3.0
ENSEMBLE_SUFFIX = "_ensemble"  # stickslip.ensemble.SUFFIX (io may not import from the orchestration layer)
KINDS = ("value", "ratio", "compare", "trend")
RELATIONS = {">": operator.gt, "<": operator.lt, ">=": operator.ge, "<=": operator.le}


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
    #: what the paper states: its number (value, ratio), or its words for a comparison ("a > b") or a trend
    #: ("increases"), never a model number
    reported: float | str
    unit: str
    measured: float
    #: a comparison's model number on the other side (its right-hand side); NaN for the other kinds
    reference: float
    deviation: float
    margin: float  #: distance of the decision variable to the claim's threshold
    spread: float  #: range of the decision variable across the perturbation ensemble (NaN: none)
    status: str
    expected: str
    matches_expected: bool
    reason: str
    quote: str


def _row_errors(exc) -> str:
    from .typed_errors import typed_errors  # the config's format of a pydantic error: ``key: message``

    return typed_errors(exc).replace("\n", "; ")


def load_claims(paths) -> list[dict]:
    """Every row of the claims files, each checked against ``ClaimRow`` (stickslip.io.claim_rows); an error
    names the file, the row's id and the key. Rows come back as plain mappings (the measuring functions
    read them by key) with the file they came from in ``_file``."""
    from pydantic import ValidationError

    from .claim_rows import ClaimRow
    from .yaml_files import YamlFileError, load_yaml

    claims, seen = [], {}
    for path in sorted(Path(p) for p in paths):
        try:
            rows = load_yaml(path) or []
        except YamlFileError as exc:
            raise ClaimsError(str(exc)) from None
        if not isinstance(rows, list):
            raise ClaimsError(f"{path}: expected a list of claim rows")
        for i, row in enumerate(rows):
            where = f"{path}: row {i} ({row.get('id', '?') if isinstance(row, dict) else '?'})"
            if not isinstance(row, dict):
                raise ClaimsError(f"{where}: expected a mapping")
            try:
                ClaimRow.model_validate(row)
            except ValidationError as exc:
                raise ClaimsError(f"{where}: {_row_errors(exc)}") from None
            if row["id"] in seen:
                raise ClaimsError(f"{where}: id {row['id']!r} already used in {seen[row['id']]}")
            seen[row["id"]] = path
            claims.append({**row, "_file": str(path)})
    return claims


def check_claims(
    claims: list[dict], readings, known_readings=None, pinned_ids=None, producible=None, variables_of=None
) -> None:
    """What a row alone cannot show: per-reading entries name known readings; the set of claim ids is the
    pinned one (a deleted row or file is an error listing the ids it lost); every dataset a claim reads,
    per claims reading (``readings``), is an output of some rule (``producible(path) -> bool``), and names a
    variable that dataset holds where ``variables_of(path)`` knows them (None: not known)."""
    known = set(known_readings or ())
    for c in claims if known_readings is not None else []:
        where = f"{c['_file']}: claim {c['id']}"
        for key in ("expected", "note"):
            if isinstance(c.get(key), dict):
                for name in c[key]:
                    if name != "default" and name not in known:
                        raise ClaimsError(f"{where}: {key}.{name}: not a reading ({sorted(known)})")
    if pinned_ids is not None:
        ids = {c["id"] for c in claims}
        lost, new = sorted(set(pinned_ids) - ids), sorted(ids - set(pinned_ids))
        if lost:
            raise ClaimsError(f"claims pinned but not found in any claims file: {', '.join(lost)}")
        if new:
            raise ClaimsError(
                f"claims not in the pinned id list (add them to it deliberately): {', '.join(new)}"
            )
    if producible is not None:
        for c in claims:
            refs = [("dataset", c)] + [
                (f"{k}.dataset", c[k]) for k in ("lhs", "rhs") if isinstance(c.get(k), dict)
            ]
            for key, ref in refs:
                if "dataset" not in ref:
                    continue
                for r in readings_of(c, readings) if "{reading}" in ref["dataset"] else [""]:
                    path = ref["dataset"].format(reading=r)
                    if not producible(path):
                        raise ClaimsError(f"{c['_file']}: claim {c['id']}: {key}: no rule writes {path!r}")
                    known_vars = variables_of(path) if variables_of is not None else None
                    if known_vars is not None and ref["variable"] not in known_vars:
                        var_key = key.replace("dataset", "variable")
                        raise ClaimsError(
                            f"{c['_file']}: claim {c['id']}: {var_key}: {ref['variable']!r} is not a "
                            f"variable that {path!r} holds"
                        )


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


def _member_values(open_dataset: Callable, ref: dict, reading: str) -> np.ndarray:
    """A dataset's scalar variable per perturbation-ensemble member (base run first), or a constant given as
    ``{value: number}``. Without an ensemble in the dataset: the base value alone."""
    if "value" in ref and "dataset" not in ref:
        return np.array([float(ref["value"])])
    ds = open_dataset(ref["dataset"].format(reading=reading))
    if ref["variable"] not in ds:
        return np.array([np.nan])
    base = float(np.asarray(ds[ref["variable"]].values).reshape(-1)[0])
    members = ds.get(ref["variable"] + ENSEMBLE_SUFFIX)
    if members is None:
        return np.array([base])
    values = np.asarray(members.values, dtype=float).reshape(members.shape[0], -1)[:, 0]
    return np.concatenate([[base], values[1:]])


def _pairwise(f: Callable, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """f over the members of two quantities: member by member when both come from one ensemble layout,
    otherwise over every pair (the conservative range). Index 0 is always the base runs' value."""
    if a.size == b.size or a.size == 1 or b.size == 1:
        with np.errstate(divide="ignore", invalid="ignore"):
            return f(a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        return f(a[:, None], b[None, :]).reshape(-1)


def spread_of(values: np.ndarray) -> float:
    """Range of a decision variable across the ensemble: NaN without an ensemble, inf when a member has
    nothing to measure but the base run has (the outcome itself moved)."""
    if values.size < 2:
        return float("nan")
    if not np.all(np.isfinite(values)):
        return float("inf")
    return float(np.ptp(values))


@dataclass
class Measurement:
    """What one claim kind measures: the base run's number(s) and a scalar *decision variable* whose side of
    a threshold decides the claim, its distance to that threshold (margin) and its ensemble range
    (spread), both in the decision variable's units."""

    reported: float | str = float("nan")
    measured: float = float("nan")
    deviation: float = float("nan")
    reference: float = float("nan")
    quantity: str = ""
    holds: bool | None = None
    detail: str = ""
    margin: float = float("nan")
    spread: float = float("nan")


def _tolerance_band(claim: dict, reported: float) -> float:
    """Half-width of the accepted interval around the reported number (the larger of rel and abs)."""
    tol = claim.get("tolerance", {})
    band = [float(tol["abs"])] if "abs" in tol else []
    if "rel" in tol:
        band.append(float(tol["rel"]) * abs(reported))
    return max(band) if band else 0.0


def decide_value(claim: dict, measured: float) -> tuple[bool, float]:
    """(holds, margin) of a value/ratio claim for one measured number."""
    reported = float(claim["value"])
    band = _tolerance_band(claim, reported)
    distance = abs(measured - reported)
    return bool(distance <= band), abs(distance - band)


def measure_value(claim: dict, reading: str, open_dataset: Callable) -> Measurement:
    out = Measurement(reported=float(claim["value"]), quantity=str(claim.get("variable", "")))
    if claim["kind"] == "value":
        members = _member_values(open_dataset, claim, reading)
    else:
        lhs = _member_values(open_dataset, claim["lhs"], reading)
        rhs = _member_values(open_dataset, claim["rhs"], reading)
        members = _pairwise(lambda a, b: np.where(b != 0, a / np.where(b != 0, b, 1.0), np.nan), lhs, rhs)
        out.quantity = f"{_name(claim['lhs'])} / {_name(claim['rhs'])}"
    out.measured = float(members[0])
    if math.isfinite(out.measured):
        r = out.reported
        out.deviation = (out.measured - r) / abs(r) if r != 0 else out.measured - r
        out.holds, out.margin = decide_value(claim, out.measured)
        out.spread = spread_of(members)
        out.detail = f"measured {out.measured:.4g} vs reported {r:.4g} ({100 * out.deviation:+.1f} %)"
    return out


def measure_compare(claim: dict, reading: str, open_dataset: Callable) -> Measurement:
    lhs = _member_values(open_dataset, claim["lhs"], reading)
    rhs = _member_values(open_dataset, claim["rhs"], reading)
    rel = claim["relation"]
    statement = f"{_name(claim['lhs'])} {rel} {_name(claim['rhs'])}"
    out = Measurement(
        reported=statement,  # the paper states a relation, not a number
        measured=float(lhs[0]),
        reference=float(rhs[0]),
        quantity=statement,
    )
    if math.isfinite(out.measured) and math.isfinite(out.reference):
        difference = _pairwise(np.subtract, lhs, rhs)  # the decision variable: lhs - rhs against 0
        out.holds = bool(RELATIONS[rel](out.measured, out.reference))
        out.margin = abs(float(difference[0]))
        out.spread = spread_of(difference)
        out.detail = f"{out.measured:.4g} {rel} {out.reference:.4g} is {out.holds}"
    return out


def _trend_change(claim: dict, x: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """(least-squares slope, fitted change relative to the mean) of y along x; NaN when not measurable."""
    if claim.get("coord_scale") == "log":  # decade sweeps: the trend per decade
        x = np.log10(np.where(x > 0, x, np.nan))
    ok = np.isfinite(x) & np.isfinite(y)
    if ok.sum() < 2 or np.ptp(x[ok]) <= 0:
        return float("nan"), float("nan")
    slope = float(np.polyfit(x[ok], y[ok], 1)[0])
    return slope, float(relative_change(slope, x[ok], y[ok]))


def decide_trend(claim: dict, change: float) -> tuple[bool, float, float]:
    """(holds, margin, direction) of a trend claim for one relative change: |change| below the floor is no
    trend, so the thresholds sit at +-floor."""
    floor = float(claim.get("min_relative_change", TREND_FLOOR))
    direction = 0.0 if abs(change) < floor else float(np.sign(change))
    return bool(direction == np.sign(float(claim["sign"]))), abs(abs(change) - floor), direction


def measure_trend(claim: dict, reading: str, open_dataset: Callable) -> Measurement:
    ds = open_dataset(claim["dataset"].format(reading=reading))
    says = "increases" if float(claim["sign"]) > 0 else "decreases"
    out = Measurement(
        reported=f"{claim['variable']} {says} with {claim['coord']}",  # the paper's words, not a number
        quantity=f"d {claim['variable']} / d {claim['coord']}",
    )
    if claim["variable"] not in ds or claim["coord"] not in ds.variables:
        return out
    x = np.asarray(ds[claim["coord"]].values, dtype=float).reshape(-1)
    y = np.asarray(ds[claim["variable"]].values, dtype=float).reshape(-1)
    out.measured, change = _trend_change(claim, x, y)
    if not math.isfinite(change):
        return out
    out.holds, out.margin, direction = decide_trend(claim, change)
    members = ds.get(claim["variable"] + ENSEMBLE_SUFFIX)
    if members is not None:
        rows = np.asarray(members.values, dtype=float).reshape(members.shape[0], -1)
        changes = [change] + [_trend_change(claim, x, row)[1] for row in rows[1:]]
        out.spread = spread_of(np.array(changes))
    words = {1.0: "rising", -1.0: "falling", 0.0: "no trend"}[direction]
    out.detail = f"slope {out.measured:.4g}: {100 * change:+.1f} % of the mean over the range ({words})"
    return out


#: One function per claim kind.
MEASURE = {"value": measure_value, "ratio": measure_value, "compare": measure_compare, "trend": measure_trend}


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


def status_of(m: Measurement, comparable: bool, failures: list[str]) -> tuple[str, str]:
    """(status, detail). A margin below MARGIN_FACTOR spreads (or an outcome that moves between ensemble
    members) is ``indistinguishable``: the numbers cannot tell. A spread of exactly 0 decides even at a
    margin of 0 (every member computes the same numbers, e.g. no separation at all: 0 > 0 is robustly
    false)."""
    if failures:  # a failed run measures nothing: never compare its numbers
        return "not-comparable", "solver failed (" + "; ".join(failures) + ")"
    if not comparable:
        return "not-comparable", m.detail
    if m.holds is None:
        return "not-comparable", m.detail or "not measurable in this reading (variable missing or NaN)"
    if math.isinf(m.spread) or (math.isfinite(m.spread) and m.margin < MARGIN_FACTOR * m.spread):
        why = (
            "an ensemble member has nothing to measure"
            if math.isinf(m.spread)
            else f"margin {m.margin:.3g} < {MARGIN_FACTOR:g} x spread {m.spread:.3g}"
        )
        return "indistinguishable", f"{m.detail} - {why}: below the numerical noise"
    return ("reproduced" if m.holds else "deviates"), m.detail


def evaluate(claim: dict, reading: str, open_dataset: Callable) -> ClaimResult:
    opened: list = []  # every dataset this claim reads, to refuse numbers from a failed solver run

    def recording_open(path, _open=open_dataset):
        ds = _open(path)
        opened.append((path, ds))
        return ds

    m = MEASURE[claim["kind"]](claim, reading, recording_open)
    status, detail = status_of(m, claim.get("comparable", True) is not False, solver_failures(opened))
    note = _per_reading(claim.get("note"), reading)
    reason = "; ".join(s for s in (detail, note if status != "reproduced" else "") if s)
    expected = _per_reading(claim["expected"], reading, default="(not pinned)")
    return ClaimResult(
        claim=claim["id"],
        reading=reading,
        section=str(claim["section"]),
        figure=str(claim["figure"]),
        kind=claim["kind"],
        quantity=m.quantity,
        reported=m.reported,
        unit=str(claim.get("unit", "")),
        measured=m.measured,
        reference=m.reference,
        deviation=m.deviation,
        margin=m.margin,
        spread=m.spread,
        status=status,
        expected=expected,
        matches_expected=(status == expected),
        reason=reason,
        quote=" ".join(str(claim["quote"]).split()),
    )


def evaluate_all(claims: list[dict], readings: list[str], open_dataset: Callable) -> list[ClaimResult]:
    return [evaluate(c, r, open_dataset) for c in claims for r in readings_of(c, readings)]


FIELDS = [f for f in ClaimResult.__dataclass_fields__]


def _cell(value) -> str:
    """A number to 4 significant digits, words as they are."""
    return f"{value:.4g}" if isinstance(value, float | int) else str(value)


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
            "| claim | reading | figure | quantity | reported | measured | unit | margin | spread | status "
            "| expected | reason |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in results:
            flag = "" if r.matches_expected else " **(changed)**"
            lines.append(
                f"| {r.claim} | {r.reading or '-'} | {r.figure} | {r.quantity} | {_cell(r.reported)} | "
                f"{r.measured:.4g} | {r.unit} | {r.margin:.3g} | {r.spread:.3g} | {r.status}{flag} | "
                f"{r.expected} | {r.reason} |"
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
