"""Straight-line chi-square profiles along every direction of a best fit (a diagnostic: the study's
dimensions are the equations', ``structure``, and what the data bound is the profile likelihood's,
``profile``, which also follows curved valleys; this module sees their tangent only).

A Jacobian's numerical rank cannot tell a direction along which chi-square rises by 1e-6 over the whole
physical range (a near-exact ridge) from a pinned one; the data's own precision decides here:

1. *Directions* (unit vectors in log10 of the free parameters at the best fit u0): the structural null space
   (the complement of ``Problem.identifiable_basis``: the same motion) and the right-singular vectors of the
   residual Jacobian in the identifiable coordinates (central differences with step ``JACOBIAN_STEP``).
   Every direction is profiled, not only those of small singular value.
2. *Profile* (``profile``): chi2(u0 + t d), stepping out on each side until chi-square exceeds the smallest
   value seen by ``PROFILE_THRESHOLD`` (1: one reading precision on one number) or the bounds are reached
   (config ``inverse.bounds`` and the plateau constraint); an infeasible set ends it.
3. *Ridge*: a direction within the threshold up to the bounds on both sides, or one no number constrains to
   first order (m numbers fix at most m directions). Identifiable dimensions: free parameters minus ridges.

A parameter along the ridges is a *range*: the extent of the flat set within the bounds, a linear programme
over the ridge directions (structural ones free, a profiled one within its interval; the bounds and sigma
v_p <= 1 are linear in log10). Limits: a profile is a straight line, its grid doubles outward (a bump
narrower than a step is not seen), and two profiled ridges are not checked jointly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import linprog

from .forward import Forward
from .problem import COMBINATIONS, Problem

#: Delta chi-square of the data's precision: residuals are in reading-precision units, so 1 is one number
#: moved by its full precision.
PROFILE_THRESHOLD = 1.0
#: Smallest first profile step [log10 units] (a factor 1.0116); each further step doubles it.
PROFILE_FIRST_STEP = 0.005
#: Central-difference step of the Jacobian in the identifiable coordinates [log10 units]: a factor 1.023,
#: above the sampling granularity of the time-series metrics (0.01 s spacing), so steps see the slope.
JACOBIAN_STEP = 0.01
#: A parameter whose log10 extent over the flat set exceeds this is reported as a range, not a point.
RANGE_MIN_WIDTH_LOG10 = 1e-6


@dataclass(frozen=True)
class Profile:
    direction: np.ndarray
    """Unit vector over the free parameters (log10)."""
    singular_value: float
    """Of the identifiable-coordinate Jacobian; 0 for a structural (exactly flat) direction."""
    structural: bool
    unconstrained: bool
    """A direction beyond the number of reported numbers: no number constrains it to first order."""
    t_lower: float
    t_upper: float
    """Interval of t [log10 units] around the best fit within the threshold (or to the bounds)."""
    bound_lower: bool
    bound_upper: bool
    """True where the profile reached the parameter bounds within the threshold."""
    rise: float
    """Largest chi-square rise above the profile's minimum within [t_lower, t_upper]."""

    @property
    def ridge(self) -> bool:
        return (self.bound_lower and self.bound_upper) or self.unconstrained


@dataclass(frozen=True)
class Identification:
    profiles: tuple
    free: int

    @property
    def ridge_directions(self) -> list[Profile]:
        return [p for p in self.profiles if p.ridge]

    @property
    def dimensions(self) -> int:
        return self.free - len(self.ridge_directions)


def _chi2(forward: Forward, u: np.ndarray) -> float:
    r = forward.residuals(10.0**u)
    return float(r @ r) if np.all(np.isfinite(r)) else np.inf


def bound_step(problem: Problem, u0: np.ndarray, d: np.ndarray, sign: float) -> float:
    """Largest t >= 0 with u0 + sign t d within the bounds (``shift_constraints`` along one direction)."""
    a, b = shift_constraints(problem, (sign * d)[:, None], u0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return float(max(0.0, np.min(np.where(a[:, 0] > 0, b / a[:, 0], np.inf))))


def profile(forward: Forward, u0: np.ndarray, d: np.ndarray, chi2_0: float, slope=0.0, ends_first=False):
    """(t_lower, t_upper, reached lower bound, reached upper bound, largest rise) along d.

    The first step on each side is where the linearisation predicts a rise of half the threshold (at least
    PROFILE_FIRST_STEP; without a slope an eighth of the way to the bound); each further step doubles it, up
    to the bound, the last point on it. ``ends_first``: a direction known to be flat (structural, or beyond
    the number of reported numbers) is evaluated on each bound first; within the threshold there, that side
    is done, else it is stepped out as any other.
    """
    seen, points, ends, reached = [chi2_0], {0.0: chi2_0}, [], []
    for sign in (-1.0, 1.0):
        limit = bound_step(forward.problem, u0, d, sign) * (1 - 1e-9)
        first = np.sqrt(PROFILE_THRESHOLD / 2) / slope if slope > 0 and np.isfinite(slope) else limit / 8
        first = max(PROFILE_FIRST_STEP, float(first))
        t_in, hit, k = 0.0, limit <= 0.0, 0
        if ends_first and not hit:
            c = points[sign * limit] = _chi2(forward, u0 + sign * limit * d)
            if c <= min(seen) + PROFILE_THRESHOLD:
                seen.append(c)
                ends.append(sign * limit)
                reached.append(True)
                continue
        while not hit:
            t = min(first * 2.0**k, limit)
            c = points[sign * t] = _chi2(forward, u0 + sign * t * d)
            seen.append(c)
            if not (c <= min(seen) + PROFILE_THRESHOLD):
                break
            t_in, hit, k = t, t >= limit, k + 1
        ends.append(sign * t_in)
        reached.append(hit)
    inside = [c for t, c in points.items() if ends[0] <= t <= ends[1] and np.isfinite(c)]
    rise = max(inside) - min(seen) if inside else np.nan
    # a later, lower minimum can leave earlier points above the threshold: the interval is then the
    # connected run around the best fit, as stepped; ``rise`` reports how flat it was
    return ends[0], ends[1], reached[0], reached[1], float(rise)


def directions(problem: Problem, forward: Forward, u0: np.ndarray) -> list[tuple]:
    """(unit direction, singular value, structural, unconstrained) for every direction of the free log10
    space; unconstrained: beyond the rank the number of reported numbers allows."""
    basis = problem.identifiable_basis()
    k = basis.shape[1]
    out = [(_signed(v), 0.0, True, False) for v in problem.null_basis().T]  # the same motion
    jw = jacobian_w(forward, basis, u0)
    if not np.all(np.isfinite(jw)):  # a neighbour infeasible: the coordinate axes themselves are profiled
        out += [(_signed(basis[:, j]), np.nan, False, False) for j in range(k)]
        return out
    _, s, vt = np.linalg.svd(jw, full_matrices=True)
    m = len(s)  # min(numbers, k): directions m.. k-1 have no singular value at all
    s = np.concatenate([s, np.zeros(k - m)])
    for j in np.argsort(s, kind="stable"):  # weakest first
        out.append((_signed(basis @ vt[j]), float(s[j]), False, bool(j >= m)))
    return out


def jacobian_w(forward: Forward, basis: np.ndarray, u0: np.ndarray) -> np.ndarray:
    """d residual / d w at u0 (w: coordinates along the columns of ``basis``), central differences."""
    cols = [
        (forward.residuals(10.0 ** (u0 + e)) - forward.residuals(10.0 ** (u0 - e))) / (2 * JACOBIAN_STEP)
        for e in basis.T * JACOBIAN_STEP
    ]
    return np.array(cols).T if cols else np.zeros((len(forward.problem.observations), 0))


def _signed(v: np.ndarray) -> np.ndarray:
    v = np.asarray(v, dtype=float) / np.linalg.norm(v)
    return v * np.sign(v[np.argmax(np.abs(v))])


def identify(forward: Forward, free_values) -> Identification:
    """Profile chi-square along every direction at ``free_values`` (a best fit); see the module text."""
    p = forward.problem
    u0 = np.log10(np.asarray(free_values, dtype=float))
    chi2_0 = _chi2(forward, u0)
    if not np.isfinite(chi2_0):
        raise ValueError(f"{p.name}/{p.family}: the best fit is infeasible; nothing to profile")
    profiles = []
    for d, s, structural, unconstrained in directions(p, forward, u0):
        ends = profile(forward, u0, d, chi2_0, s, structural or unconstrained)
        profiles.append(Profile(d, s, structural, unconstrained, *ends))
    return Identification(tuple(profiles), len(p.free))


def shift_constraints(problem: Problem, d: np.ndarray, u) -> tuple[np.ndarray, np.ndarray]:
    """(A, b) with A s <= b for a shift s along the columns of ``d`` keeping u + d s within the bounds: the
    box and, with the plateau constraint, sigma v_p <= 1 (both linear in log10)."""
    lo, hi = problem.log_bounds
    a, b = [d, -d], [hi - u, u - lo]
    if problem.plateau_pair is not None:
        i, j = problem.plateau_pair
        a.append((d[i] + d[j])[None, :])
        b.append(np.array([-(u[i] + u[j])]))
    return np.vstack(a), np.concatenate(b)


def flat_extent(problem: Problem, free_values, ident: Identification, rows: np.ndarray) -> np.ndarray:
    """(lower, upper) log10 change of each row . u over the flat set (LP over the ridge directions).

    ``rows`` are linear functionals over the free log10 parameters (a unit row: a parameter; a
    combination's exponents: that combination). Without ridges every extent is (0, 0).
    """
    rows = np.atleast_2d(np.asarray(rows, dtype=float))
    ridges = ident.ridge_directions
    if not ridges:
        return np.zeros((len(rows), 2))
    d = np.column_stack([r.direction for r in ridges])
    a_ub, b_ub = shift_constraints(problem, d, np.log10(np.asarray(free_values, dtype=float)))
    box = [(None, None) if r.structural else (r.t_lower, r.t_upper) for r in ridges]
    return lp_extent([row @ d for row in rows], a_ub, b_ub, box)[0]


def lp_extent(costs, a_ub, b_ub, bounds=(None, None)) -> tuple[np.ndarray, list]:
    """(lowest, highest) of each ``c . s`` over the shifts s with ``A s <= max(b, 0)`` within ``bounds`` (NaN
    where the programme fails), and the shifts where each is reached."""
    out, shifts = np.full((len(costs), 2), np.nan), []
    for n, c in enumerate(costs):
        for col, sign in ((0, 1.0), (1, -1.0)):
            res = linprog(sign * c, A_ub=a_ub, b_ub=np.maximum(b_ub, 0.0), bounds=bounds, method="highs")
            if res.status == 0:
                out[n, col] = sign * res.fun
                shifts.append(res.x)
    return out, shifts


def parameter_ranges(problem: Problem, free_values, ident: Identification) -> tuple[np.ndarray, np.ndarray]:
    """(lower, upper) of each free parameter over the flat set (equal to the best fit where pinned)."""
    v = np.asarray(free_values, dtype=float)
    ext = flat_extent(problem, v, ident, np.eye(len(problem.free)))
    return v * 10.0 ** ext[:, 0], v * 10.0 ** ext[:, 1]


def combination_rows(problem: Problem) -> dict[str, np.ndarray]:
    """log10 exponents of each combination over the free parameters (fixed parameters are constants)."""
    return {
        name: np.array([float(combo.get(p, 0)) for p in problem.free])
        for name, combo in COMBINATIONS.items()
        if any(p in problem.free for p in combo)
    }


def quantity_rows(problem: Problem) -> dict[str, np.ndarray]:
    """log10 exponents over the free parameters of each free parameter, then of each combination (a
    one-parameter one, sigma, keeps its parameter's place)."""
    return {**dict(zip(problem.free, np.eye(len(problem.free)))), **combination_rows(problem)}


def on_ridge(lower, upper) -> np.ndarray:
    """True where a value moves along the flat set (reported as a range, never as a point)."""
    lower, upper = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log10(upper / lower) > RANGE_MIN_WIDTH_LOG10
