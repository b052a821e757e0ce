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
stickslip.ensemble). One rule for every kind, at every disc speed and in every reading: a margin below
MARGIN_FACTOR spreads is ``indistinguishable`` (the spread includes the dt/2 run). Unanimity of the members
alone is not enough: with a handful of members it would decide ties such as 0.75 > 0.75 in a reading whose
end state is set by round-off. A value the step-halving check withheld still decides a comparison through
its two steps' values (its side, when both lie beyond 3 spreads of it). ``expected`` pins the
status (one string, or one per reading); the check fails when a measured status differs from the pinned
one, so every change is deliberate.
"""

from __future__ import annotations

import csv
import math
import operator
import sys
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from .claim_models import MODEL_VALUES, NOT_ADEQUATE

STATUSES = ("reproduced", "deviates", "indistinguishable", "not-comparable")

#: A claim is decided only when its margin to the threshold exceeds this many ensemble spreads.
MARGIN_FACTOR = 3.0
#: ... and this fraction of the numbers it compares: every metric is read off a sampled trajectory over a
#: finite window (sample spacing, where the window ends), which the perturbation ensemble does not vary, so
#: two numbers that agree to 0.1 % (a rest position reached in both runs, 0.75 vs 0.75) are not ordered.
RESOLUTION = 1e-3

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
    #: what the row can show (stickslip.io.claim_rows.EVIDENCE_CLASSES); only ``evidence`` is counted
    evidence: str
    #: one conclusion sentence (at most CONCLUSION_LENGTH characters), then the numbers, then the caveats
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
    _check_speed_twins(claims)
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


#: The two disc speeds of the beam-on-disc scenes, as their dataset names spell them.
DISC_SPEEDS = ("15p2rpm", "0p5mm_s")


def disc_speed(claim: dict) -> str:
    """The disc speed a claim reads (one of DISC_SPEEDS), ``""`` for none or several."""
    found = {s for p in dataset_paths(claim) for s in DISC_SPEEDS if f"_{s}" in p}
    return found.pop() if len(found) == 1 else ""


def _check_speed_twins(claims: list[dict]) -> None:
    """Every claim read at one disc speed is decided at the other too (``twin``: the row that does, reading
    the other speed, and naming this row back) or says why not (``one_speed``)."""
    by_id = {c["id"]: c for c in claims}
    for c in claims:
        where = f"{c['_file']}: claim {c['id']}"
        speed = disc_speed(c)
        if c.get("twin") is None:
            if speed and not c.get("one_speed"):
                raise ClaimsError(
                    f"{where}: reads the {speed} scenes only: add its twin at the other speed (twin: <id>) "
                    "or say why not (one_speed: <reason>)"
                )
            continue
        twin = by_id.get(c["twin"])
        if twin is None:
            raise ClaimsError(f"{where}: twin: {c['twin']!r} is not a claim id")
        if twin.get("twin") != c["id"]:
            raise ClaimsError(f"{where}: twin: {c['twin']!r} does not name {c['id']!r} back")
        if not speed or disc_speed(twin) in ("", speed):
            raise ClaimsError(f"{where}: twin: {c['twin']!r} does not read the other disc speed")


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


def withheld_values(ds, variable: str) -> tuple[float, float] | None:
    """(value at dt, value at dt/2) of a metric the step-halving check withheld (NaN in the dataset, both
    steps' values kept beside it: stickslip.fe.step_halving); None when nothing was withheld."""
    if variable not in ds or f"{variable}_full_step" not in ds or f"{variable}_half_step" not in ds:
        return None
    if np.isfinite(np.asarray(ds[variable].values, dtype=float).reshape(-1)[0]):
        return None
    full = float(np.asarray(ds[f"{variable}_full_step"].values, dtype=float).reshape(-1)[0])
    half = float(np.asarray(ds[f"{variable}_half_step"].values, dtype=float).reshape(-1)[0])
    return full, half


def _member_values(
    open_dataset: Callable, ref: dict, reading: str, side_only: bool = False, notes: list | None = None
) -> np.ndarray:
    """A dataset's scalar variable per perturbation-ensemble member (base run first), or a constant given as
    ``{value: number}``. Without an ensemble in the dataset: the base value alone.

    A value withheld for moving under step halving is NaN here, its two steps' values named in ``notes``;
    with ``side_only`` (a claim that reads only which side of a threshold the value is on) those two values
    are the members: the side is decided when both steps agree on it beyond the noise, as for growth."""
    if "value" in ref and "dataset" not in ref:
        return np.array([float(ref["value"])])
    ds = open_dataset(ref["dataset"].format(reading=reading))
    if ref["variable"] not in ds:
        return np.array([np.nan])
    withheld = withheld_values(ds, ref["variable"])
    if withheld is not None:
        if notes is not None:
            full, half = withheld
            notes.append(f"{ref['variable']} moves under step halving ({full:.3g} at dt, {half:.3g} at dt/2)")
        if side_only:
            return np.array(withheld)
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
    #: what was computed but not used (values withheld by the step-halving check), for the reason
    withheld: list = field(default_factory=list)
    #: size of the numbers the decision compares (the resolution floor is RESOLUTION x scale)
    scale: float = 1.0


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
        members = _member_values(open_dataset, claim, reading, notes=out.withheld)
    else:
        lhs = _member_values(open_dataset, claim["lhs"], reading, notes=out.withheld)
        rhs = _member_values(open_dataset, claim["rhs"], reading, notes=out.withheld)
        members = _pairwise(lambda a, b: np.where(b != 0, a / np.where(b != 0, b, 1.0), np.nan), lhs, rhs)
        out.quantity = f"{_name(claim['lhs'])} / {_name(claim['rhs'])}"
    out.measured = float(members[0])
    if math.isfinite(out.measured):
        r = out.reported
        out.deviation = (out.measured - r) / abs(r) if r != 0 else out.measured - r
        out.holds, out.margin = decide_value(claim, out.measured)
        out.scale = abs(r)
        out.spread = spread_of(members)
        out.detail = f"measured {out.measured:.4g} vs reported {r:.4g} ({100 * out.deviation:+.1f} %)"
    return out


def measure_compare(claim: dict, reading: str, open_dataset: Callable) -> Measurement:
    withheld: list = []
    lhs = _member_values(open_dataset, claim["lhs"], reading, side_only=True, notes=withheld)
    rhs = _member_values(open_dataset, claim["rhs"], reading, side_only=True, notes=withheld)
    rel = claim["relation"]
    statement = f"{_name(claim['lhs'])} {rel} {_name(claim['rhs'])}"
    out = Measurement(
        reported=statement,  # the paper states a relation, not a number
        measured=float(lhs[0]),
        reference=float(rhs[0]),
        quantity=statement,
        withheld=withheld,
    )
    if math.isfinite(out.measured) and math.isfinite(out.reference):
        difference = _pairwise(np.subtract, lhs, rhs)  # the decision variable: lhs - rhs against 0
        out.holds = bool(RELATIONS[rel](out.measured, out.reference))
        out.margin = abs(float(difference[0]))
        out.scale = max(abs(out.measured), abs(out.reference))
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


def member_failures(opened: list) -> list[str]:
    """The failed members of the sweeps a claim read (``solver_ok`` = 0), each with its parameter value and
    ``failure_message``: a trend is fitted over the others, so these are caveats, not a failed claim."""
    out = []
    for _path, ds in opened:
        ok = ds.variables.get("solver_ok") if hasattr(ds, "variables") else None
        if ok is None or ok.ndim != 1 or "failure_message" not in ds.variables:
            continue
        dim = ok.dims[0]
        coord = ds[dim].values if dim in ds.coords else np.arange(ok.size)
        for value, good, message in zip(coord, np.asarray(ok.values), ds["failure_message"].values):
            if good != 1:
                out.append(f"{dim} = {value:g} failed ({message})")
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
        if m.withheld:
            return "not-comparable", "withheld: " + "; ".join(m.withheld)
        return "not-comparable", m.detail or "nothing computed in this reading (variable missing or NaN)"
    if math.isinf(m.spread) or (math.isfinite(m.spread) and m.margin < MARGIN_FACTOR * m.spread):
        why = (
            "an ensemble member has nothing to measure"
            if math.isinf(m.spread)
            else f"margin {m.margin:.3g} < {MARGIN_FACTOR:g} x spread {m.spread:.3g}"
        )
        return "indistinguishable", f"{m.detail} - {why}: below the numerical noise"
    if m.margin < RESOLUTION * m.scale:
        why = f"margin {m.margin:.3g} < {RESOLUTION:g} x {m.scale:.3g}: the numbers agree to 0.1 %"
        return "indistinguishable", f"{m.detail} - {why}, below what a sampled run resolves"
    return ("reproduced" if m.holds else "deviates"), m.detail


#: Longest conclusion sentence of a reason (what a reader scans before the numbers).
CONCLUSION_LENGTH = 120


def _short(text: str, limit: int) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1].rstrip(" ,;:(") + "…"


def conclusion(claim: dict, m: Measurement, status: str, failures: list[str]) -> str:
    """One sentence that says what the row concludes, at most CONCLUSION_LENGTH characters."""
    kind = claim["kind"]
    if status == "not-comparable":
        if failures:
            why = "the solver run failed"
        elif claim.get(NOT_ADEQUATE):
            why = "the beam is not the paper's model here (model comparison)"
        elif claim.get("comparable", True) is False:
            why = "the paper contradicts this sentence elsewhere"
        elif m.withheld:
            why = "the value moves under step halving, so it is withheld"
        else:
            why = "nothing to measure in this run"
        text = f"Not comparable: {why}."
    elif status == "indistinguishable":
        text = "Undecided: the margin to the threshold is within the run's own numerical noise."
    else:
        verb = "Reproduced" if status == "reproduced" else "Deviates"
        if kind in ("value", "ratio"):
            unit = "" if claim.get("unit") in (None, "1") else f" {claim['unit']}"
            text = (
                f"{verb}: {m.measured:.3g}{unit} against the paper's {float(m.reported):.3g}{unit} "
                f"({100 * m.deviation:+.0f} %)."
            )
        elif kind == "compare":
            says = "holds" if m.holds else "does not hold"
            text = f"{verb}: the paper's {m.quantity} {says} ({m.measured:.3g} vs {m.reference:.3g})."
        else:
            text = f"{verb}: the paper says {m.reported}; the run {'agrees' if m.holds else 'does not'}."
    if claim.get("evidence", "evidence") != "evidence":
        text = text[:-1] + f", {claim['evidence'].replace('_', ' ')}."
    return _short(text, CONCLUSION_LENGTH)


def reason_text(claim: dict, reading: str, m: Measurement, status: str, detail: str, failures, caveats):
    """The conclusion sentence, then the numbers, then every caveat: why the row is not evidence, values
    computed but withheld, failed sweep members, and the row's note (never dropped)."""
    parts = [conclusion(claim, m, status, failures), detail]
    if claim.get("evidence_note"):
        parts.append(f"Not evidence ({claim['evidence'].replace('_', ' ')}): {claim['evidence_note']}")
    if m.withheld and not detail.startswith("withheld"):
        parts.append("withheld: " + "; ".join(m.withheld))
    parts += caveats
    note = _per_reading(claim.get("note"), reading)
    parts.append(note)
    return " | ".join(" ".join(str(p).split()) for p in parts if p)


def evaluate(claim: dict, reading: str, open_dataset: Callable) -> ClaimResult:
    opened: list = []  # every dataset this claim reads, to refuse numbers from a failed solver run

    def recording_open(path, _open=open_dataset):
        ds = _open(path)
        opened.append((path, ds))
        return ds

    m = MEASURE[claim["kind"]](claim, reading, recording_open)
    failures = solver_failures(opened)
    adequate = not claim.get(NOT_ADEQUATE)  # set by stickslip.io.claim_models.annotate
    status, detail = status_of(m, claim.get("comparable", True) is not False and adequate, failures)
    if not adequate and not failures:
        detail = f"{claim[NOT_ADEQUATE]} | {detail}"
    members = member_failures(opened)
    caveats = [f"{len(members)} sweep runs failed: " + "; ".join(members)] if members else []
    caveats += [claim[MODEL_VALUES]] if claim.get(MODEL_VALUES) else []
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
        evidence=str(claim.get("evidence", "evidence")),
        reason=reason_text(claim, reading, m, status, detail, failures, caveats),
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
