"""How a claim is measured: one function per claim kind reduces the row to a decision variable, its margin
to the threshold and its spread across the perturbation ensemble; ``status_of`` decides from those."""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from stickslip.analysis.outcome import ANSWERS, outcome_code, outcome_name
from stickslip.ensemble import SUFFIX

from .rows import Claim, ClaimRow, Operand

#: A claim is decided only when its margin to the threshold exceeds this many ensemble spreads.
MARGIN_FACTOR = 3.0
#: ... and this fraction of the numbers it compares: every metric is read off a sampled trajectory over a
#: finite window (sample spacing, where the window ends), which the perturbation ensemble does not vary, so
#: two numbers that agree to 0.1 % (a rest position reached in both runs, 0.75 vs 0.75) are not ordered.
RESOLUTION = 1e-3

RELATIONS = {">": operator.gt, "<": operator.lt, ">=": operator.ge, "<=": operator.le}


#: A fitted change smaller than this fraction of the mean |value| over the swept range counts as no trend
#: (a directional sentence is about a visible effect, not about round-off).
TREND_FLOOR = 0.05


def relative_change(slope: float, x: np.ndarray, y: np.ndarray) -> float:
    """Fitted change over the coordinate range, relative to the mean magnitude of the variable."""
    scale = float(np.mean(np.abs(y)))
    return slope * float(np.ptp(x)) / scale if scale > 0 else (0.0 if slope == 0 else np.sign(slope) * np.inf)


def withheld_steps(ds, variable: str) -> tuple[np.ndarray, np.ndarray] | None:
    """(values at dt, values at dt/2) kept beside a metric the step-halving check withheld (NaN in the
    dataset: stickslip.fe.step_halving); None when the dataset keeps none."""
    names = (f"{variable}_full_step", f"{variable}_half_step")
    if any(name not in ds for name in names):
        return None
    return tuple(np.asarray(ds[name].values, dtype=float).reshape(-1) for name in names)


def _member_values(
    open_dataset: Callable,
    ref: ClaimRow | Operand,
    reading: str,
    side_only: bool = False,
    notes: list | None = None,
) -> np.ndarray:
    """A dataset's scalar variable per perturbation-ensemble member (base run first), or a constant (an
    operand with a value and no dataset). Without an ensemble in the dataset: the base value alone.

    A value withheld for moving under step halving is NaN here, its two steps' values named in ``notes``;
    with ``side_only`` (a claim that reads only which side of a threshold the value is on) those two values
    are the members: the side is decided when both steps agree on it beyond the noise, as for growth."""
    if ref.dataset is None:  # a value row always names its dataset: only an operand is a constant
        return np.array([float(ref.value)])
    ds = open_dataset(ref.dataset.format(reading=reading))
    if ref.variable not in ds:
        return np.array([np.nan])
    base = float(np.asarray(ds[ref.variable].values).reshape(-1)[0])
    steps = None if np.isfinite(base) else withheld_steps(ds, ref.variable)
    if steps is not None:
        full, half = (float(values[0]) for values in steps)
        if notes is not None:
            notes.append(f"{ref.variable} moves under step halving ({full:.3g} at dt, {half:.3g} at dt/2)")
        if side_only:
            return np.array([full, half])
    members = ds.get(ref.variable + SUFFIX)
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
    #: the exact invariance that makes the compared numbers equal (set when they are, within the noise)
    invariance: str = ""


def decide_value(claim: ClaimRow, measured: float) -> tuple[bool, float]:
    """(holds, margin) of a value/ratio claim for one measured number. The accepted band around the
    reported number has the half-width of the larger of rel x |value| and abs (a value or ratio row always
    has one of them, stickslip.claims.rows)."""
    reported, tol = float(claim.value), claim.tolerance
    band = max(w for w in (tol.abs, None if tol.rel is None else tol.rel * abs(reported)) if w is not None)
    distance = abs(measured - reported)
    return bool(distance <= band), abs(distance - band)


def measure_value(claim: Claim, reading: str, open_dataset: Callable) -> Measurement:
    # a ratio row holds no variable of its own: its quantity is named from its operands below
    out = Measurement(reported=float(claim.value), quantity=claim.variable or "")
    # a value withheld for moving under step halving: its two steps' values are the members, so the row is
    # decided where both lie on one side of the band beyond their difference (as a comparison's sides)
    if claim.kind == "value":
        members = _member_values(open_dataset, claim, reading, side_only=True, notes=out.withheld)
    else:
        lhs = _member_values(open_dataset, claim.lhs, reading, side_only=True, notes=out.withheld)
        rhs = _member_values(open_dataset, claim.rhs, reading, side_only=True, notes=out.withheld)
        members = _pairwise(lambda a, b: np.where(b != 0, a / np.where(b != 0, b, 1.0), np.nan), lhs, rhs)
        out.quantity = f"{_name(claim.lhs)} / {_name(claim.rhs)}"
    out.measured = float(members[0])
    if math.isfinite(out.measured):
        r = out.reported
        out.deviation = (out.measured - r) / abs(r) if r != 0 else out.measured - r
        out.holds, out.margin = decide_value(claim, out.measured)
        out.scale = abs(r)
        out.spread = spread_of(members)
        out.detail = f"measured {out.measured:.4g} vs reported {r:.4g} ({100 * out.deviation:+.1f} %)"
    return out


def measure_compare(claim: Claim, reading: str, open_dataset: Callable) -> Measurement:
    withheld: list = []
    lhs = _member_values(open_dataset, claim.lhs, reading, side_only=True, notes=withheld)
    rhs = _member_values(open_dataset, claim.rhs, reading, side_only=True, notes=withheld)
    rel = claim.relation
    statement = f"{_name(claim.lhs)} {rel} {_name(claim.rhs)}"
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
        invariance = (claim.invariance or {}).get(reading, "")
        if invariance and _equal_within_noise(out):
            out.holds, out.invariance = rel in (">=", "<="), invariance  # equal: a strict relation fails
            out.detail = f"{out.measured:.7g} and {out.reference:.7g} are equal by an exact invariance"
    return out


def _equal_within_noise(m: Measurement) -> bool:
    """The two sides agree within the ensemble's spread and the sampled resolution."""
    noise = MARGIN_FACTOR * m.spread if math.isfinite(m.spread) else 0.0
    return m.margin <= max(noise, RESOLUTION * m.scale)


def _trend_change(claim: ClaimRow, x: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """(least-squares slope, fitted change relative to the mean) of y along x; NaN when not measurable."""
    if claim.coord_scale == "log":  # decade sweeps: the trend per decade
        x = np.log10(np.where(x > 0, x, np.nan))
    ok = np.isfinite(x) & np.isfinite(y)
    if ok.sum() < 2 or np.ptp(x[ok]) <= 0:
        return float("nan"), float("nan")
    slope = float(np.polyfit(x[ok], y[ok], 1)[0])
    return slope, float(relative_change(slope, x[ok], y[ok]))


def decide_trend(claim: ClaimRow, change: float) -> tuple[bool, float, float]:
    """(holds, margin, direction) of a trend claim for one relative change: |change| below the floor is no
    trend, so the thresholds sit at +-floor. The margin is the distance to the edge that decides the claim:
    +floor for "increases", -floor for "decreases", the nearer edge for "no trend" (sign 0), so a clear fall
    is not called undecided for lying near +-floor on the wrong side."""
    floor = TREND_FLOOR if claim.min_relative_change is None else claim.min_relative_change
    direction = 0.0 if abs(change) < floor else float(np.sign(change))
    sign = float(np.sign(float(claim.sign)))
    margin = abs(abs(change) - floor) if sign == 0 else abs(sign * change - floor)
    return bool(direction == sign), margin, direction


def measure_trend(claim: Claim, reading: str, open_dataset: Callable) -> Measurement:
    ds = open_dataset(claim.dataset.format(reading=reading))
    says = "increases" if claim.sign > 0 else "decreases"
    out = Measurement(
        reported=f"{claim.variable} {says} with {claim.coord}",  # the paper's words, not a number
        quantity=f"d {claim.variable} / d {claim.coord}",
    )
    if claim.variable not in ds or claim.coord not in ds.variables:
        return out
    x = np.asarray(ds[claim.coord].values, dtype=float).reshape(-1)
    y = np.asarray(ds[claim.variable].values, dtype=float).reshape(-1)
    steps = None if np.any(np.isfinite(y)) else withheld_steps(ds, claim.variable)
    if steps is not None:  # withheld for moving under step halving: decided on both steps' trends
        y = steps[0]
    out.measured, change = _trend_change(claim, x, y)
    if not math.isfinite(change):
        return out
    out.holds, out.margin, direction = decide_trend(claim, change)
    members = ds.get(claim.variable + SUFFIX)
    if steps is not None:
        changes = [_trend_change(claim, x, s)[1] for s in steps]
        out.spread = spread_of(np.array(changes))
        out.withheld.append(
            f"{claim.variable} moves under step halving: change {100 * changes[0]:+.0f} % at dt, "
            f"{100 * changes[1]:+.0f} % at dt/2"
        )
    elif members is not None:
        rows = np.asarray(members.values, dtype=float).reshape(members.shape[0], -1)
        changes = [change] + [_trend_change(claim, x, row)[1] for row in rows[1:]]
        out.spread = spread_of(np.array(changes))
    words = {1.0: "rising", -1.0: "falling", 0.0: "no trend"}[direction]
    out.detail = f"slope {out.measured:.4g}: {100 * change:+.1f} % of the mean over the range ({words})"
    return out


#: One function per claim kind.
MEASURE = {"value": measure_value, "ratio": measure_value, "compare": measure_compare, "trend": measure_trend}


def solver_failures(opened: list) -> list[str]:
    """Messages of the numerically failed solver runs (``solver_status`` = 1) among the (path, dataset)
    pairs a claim read. A run that diverged (status 2) is the model's answer, not a failure."""
    out = []
    for path, ds in opened:
        status = ds.variables.get("solver_status") if hasattr(ds, "variables") else None
        if status is not None and np.any(np.asarray(status.values) == 1):
            out.append(f"{path}: {status.attrs.get('message', 'no message')}")
    return out


@dataclass
class ModelAnswer:
    """A run the claim read that ended without the stick-slip cycle the paper describes (it diverged,
    came to rest or never sticks): the model has answered, so a claim it leaves unmeasured is decided."""

    outcome: str
    mechanism: str
    #: the outcome is the same in every perturbation-ensemble member (else the noise decides it)
    robust: bool
    #: the decision's spread over the ensemble: 0 when every member leaves the same runs without a cycle,
    #: inf when they differ, NaN when the dataset has no ensemble
    spread: float = float("nan")


def model_answer(opened: list) -> ModelAnswer | None:
    """The first model answer (ANSWERS of stickslip.analysis.outcome) among the datasets a claim read: a
    scene run's ``outcome`` or a sweep's per-point outcomes (where no point has a cycle to measure)."""
    for _path, ds in opened:
        found = _answer_of(ds) if hasattr(ds, "variables") and "outcome" in ds.variables else None
        if found is not None:
            return found
    return None


def _answer_of(ds) -> ModelAnswer | None:
    """A scene run's answer, or a sweep's: where the claim found fewer cycles to measure than it needs,
    because runs of the sweep diverged, rest or never stick (a numerical failure among them decides
    nothing)."""
    codes = np.asarray(ds["outcome"].values, dtype=float).reshape(-1)
    names = [outcome_name(c) for c in codes]
    answered = [i for i, name in enumerate(names) if name in ANSWERS]
    if not answered or "failed" in names or "" in names:
        return None
    if ds["outcome"].ndim == 0:
        why = ds["outcome"].attrs.get("mechanism", "")
    else:
        mechanisms = (
            np.asarray(ds["outcome_mechanism"].values).reshape(-1) if "outcome_mechanism" in ds else []
        )
        first = str(mechanisms[answered[0]]) if len(mechanisms) else ""
        kinds = ", ".join(sorted({names[i].replace("_", " ") for i in answered}))
        count = f"{len(answered)} of {len(names)} runs of the sweep"
        why = f"{count} have no stick-slip cycle ({kinds}); first: {first}"
    members = ds.get("outcome" + SUFFIX)
    robust, spread = True, float("nan")
    if members is not None:  # robust: every member leaves the same runs without a cycle (whichever answer)
        values = np.asarray(members.values, dtype=float).reshape(members.shape[0], -1)
        is_answer = np.isin(values, [outcome_code(name) for name in ANSWERS])
        robust = bool(np.all(is_answer == is_answer[:1]))
        spread = 0.0 if robust else float("inf")
    return ModelAnswer(names[answered[0]], why, robust, spread)


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
                what = "diverged" if str(message).startswith("diverg") else "failed"
                out.append(f"{dim} = {value:g} {what} ({message})")
    return out


def status_of(
    m: Measurement, comparable: bool, failures: list[str], answer: ModelAnswer | None = None
) -> tuple[str, str]:
    """(status, detail). A margin below MARGIN_FACTOR spreads (or an outcome that moves between ensemble
    members) is ``indistinguishable``: the numbers cannot tell. A spread of exactly 0 decides even at a
    margin of 0 (every member computes the same numbers, e.g. no separation at all: 0 > 0 is robustly
    false). A claim left unmeasured by a model ``answer`` (the run diverged, rests or never sticks, so the
    cycle the paper describes does not exist) deviates: that is the model's answer to the paper."""
    if failures:  # a failed run measures nothing: never compare its numbers
        return "not-comparable", "solver failed (" + "; ".join(failures) + ")"
    if not comparable:
        return "not-comparable", m.detail
    if m.holds is None:
        if answer is not None and not m.withheld:
            detail = f"the model's run: {answer.outcome.replace('_', ' ')} ({answer.mechanism})"
            if not answer.robust:
                return "indistinguishable", f"{detail} - the outcome moves within the perturbation ensemble"
            return "deviates", detail
        if m.withheld:
            return "not-comparable", "withheld: " + "; ".join(m.withheld)
        return "not-comparable", m.detail or "nothing computed in this reading (variable missing or NaN)"
    if m.invariance:
        return ("reproduced" if m.holds else "deviates"), f"{m.detail}: {m.invariance}"
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


def _name(ref: Operand) -> str:
    return ref.variable if ref.variable is not None else f"{ref.value}"
