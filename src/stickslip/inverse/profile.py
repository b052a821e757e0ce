"""Identifiability by profile likelihood (Raue et al., Bioinformatics 25:1923, 2009).

The straight-line profiles of ``identify`` follow a flat valley along its tangent only; a valley that curves
in log10 coordinates rises along that line although chi-square is constant along the valley itself. Here a
quantity q (a free parameter, or a combination K/M, C/M, mu_s N/M of them: a row over the free log10
parameters) is *fixed* on a grid and chi-square is *re-minimised over everything else*:

    PL_q(t) = min { chi2(u) : row . u = row . u0 + t, u within the bounds }.

* Coordinates: the motion depends on the identifiable coordinates w only (``Problem.identifiable_basis``),
  so the minimisation runs over the k - 1 coordinates of w that keep the row fixed (least squares,
  ``PL_NFEV`` evaluations, started from the previous grid point extrapolated linearly); a set
  outside the bounds is moved along the structural null space (the same motion) into them where a linear
  programme finds room, else it is infeasible.
* Grid: t = +-t1 2^j outward from the best fit, t1 from the linearised spread of q (Gauss-Newton, at least
  ``PL_FIRST_STEP``), the last point on the bound of q; a side ends at the first point above the threshold.
  A grid point is *within* as soon as a set within the threshold is found (the profile there is at most
  that chi-square), so a flat profile costs about one run per point.
* Threshold: ``PL_THRESHOLD`` = 3.84, the 95 % quantile of chi-square with one degree of freedom: the
  pointwise 95 % confidence interval of q (its likelihood-ratio interval). Residuals are in reading-precision
  units, so chi-square is the data's own.
* q is *identifiable* when its profile exceeds the threshold on both sides within the bounds; its interval
  is then a confidence interval around the best fit. Otherwise q is a *range* (never a point): the side that
  stays within the threshold up to the bound is *open* (the data do not bound it there).
* Only the quantities the runs' structure (``structure.problem_structure``, derived from the equations)
  leaves identifiable are profiled, and the dimensions are the structure's (exact); a quantity it leaves
  free is a range over the fibre (``structure.fibre_extent``) of the best fit and of each profile's ends.

Limits: a grid point is judged by a local minimisation with a fixed budget, so a flat set reachable only
through a barrier is not seen (the profile is then an upper bound of PL_q); the grid doubles outward, so a
dip narrower than a step is not seen.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares, linprog
from scipy.stats import chi2 as chi2_distribution

from .fit import _fun, _power10
from .forward import Forward
from .identify import JACOBIAN_STEP, jacobian_w, lp_extent, quantity_rows, shift_constraints
from .problem import Problem
from .structure import fibre_extent, identifiable_in_structure, runs_rank

#: Confidence of the profile-likelihood intervals (pointwise, one parameter).
PL_CONFIDENCE = 0.95
#: Delta chi-square of PL_CONFIDENCE for one degree of freedom (3.84).
PL_THRESHOLD = float(chi2_distribution.ppf(PL_CONFIDENCE, 1))
#: Forward evaluations of the least-squares re-minimisation at one grid point (k - 1 <= 6 coordinates: one
#: Jacobian and a few steps; a flat profile stops at its first evaluation within the threshold).
PL_NFEV = 3
#: A re-minimisation stops early at chi-square within this fraction of the threshold (the next grid point is
#: extrapolated from it, so it should lie near the valley floor, not at its edge).
PL_CLOSE = 0.25
#: A set closer than this to the bounds [log10 units, a factor 1.023] ends a valley on the bounds.
PL_EDGE = 0.01
#: Halvings of a step that overshot before a side of the profile ends.
PL_HALVINGS = 2
#: A side ends on a rise of the profile (the data bound it) only if its last point within the threshold has
#: risen by this fraction of it: a smooth rise, stepped to 1/8 of a step by the halvings, ends above it; a
#: valley the re-minimisation cannot follow further (an exact ridge stays at the floor) does not.
PL_RISE = 0.25
#: Largest grid step [log10 units]: the next set is extrapolated from the last ones, which a curved valley
#: allows over a short step only.
PL_MAX_STEP = 0.2
#: Smallest first grid step [log10 units].
PL_FIRST_STEP = 0.01
#: A row whose component along the structural null space is below this does not move along it.
ROW_SPACE_TOL = 1e-9


@dataclass(frozen=True)
class LikelihoodProfile:
    t: np.ndarray
    """Offsets [log10 units] from the best fit evaluated, ascending."""
    chi2: np.ndarray
    """Profile at each offset (within: the first set found within the threshold; inf: infeasible)."""
    points: np.ndarray
    """The free parameter set reached at each offset (rows as ``t``)."""
    t_lower: float
    t_upper: float
    """Interval of offsets within the threshold, connected to the best fit."""
    open_lower: bool
    open_upper: bool
    """Within the threshold up to the bound of the quantity on that side."""

    @property
    def identifiable(self) -> bool:
        return not (self.open_lower or self.open_upper)


@dataclass(frozen=True)
class ProfileIdentification:
    profiles: dict
    """Name -> LikelihoodProfile of every quantity the structure leaves identifiable."""
    dimensions: int
    """The structural dimension (``structure.runs_rank``): exact."""
    floor: float
    """Smallest chi-square seen (the best fit's, or lower where a profile found one)."""
    structure: tuple
    """The runs' structure (``structure.problem_structure``): what the equations leave free, exactly."""


class _Within(Exception):
    def __init__(self, z):
        self.z = z


def structural_rows(problem: Problem, structure: tuple) -> dict[str, np.ndarray]:
    """The quantities to profile: free parameters, then combinations of several, whose log10 row lies in the
    row space of the runs' derived combinations (``structure.identifiable_in_structure``: an exact rank). A
    quantity the equations leave free is a range whatever the data: profiling it would only trace the fibre,
    which ``structure.fibre_extent`` gives exactly, without a forward run."""
    free = tuple(problem.free)
    return {
        name: row
        for name, row in quantity_rows(problem).items()
        if (name in free or np.count_nonzero(row) > 1)
        and identifiable_in_structure(structure, free, tuple(row))
    }


class _Space:
    """Moves in the identifiable coordinates through the best fit, kept within the bounds."""

    def __init__(self, problem: Problem, u0: np.ndarray):
        self.p, self.u0 = problem, u0
        self.basis, self.null = problem.identifiable_basis(), problem.null_basis()
        self.lo, self.hi = problem.log_bounds
        self.jacobian_w, self.r0 = None, None

    def jacobian(self, forward: Forward) -> np.ndarray:
        """d residual / d w at the best fit by central differences (step JACOBIAN_STEP), once."""
        if self.jacobian_w is None:
            self.r0 = forward.residuals(10.0**self.u0)
            self.jacobian_w = jacobian_w(forward, self.basis, self.u0)
        return self.jacobian_w

    def feasible(self, w) -> np.ndarray:
        """log10 free values with coordinates w: through the best fit, else shifted into the bounds."""
        u = self.u0 + self.basis @ w
        if self.p.in_bounds(_power10(u)) or self.null.shape[1] == 0:
            return u
        a, b = shift_constraints(self.p, self.null, u)
        res = linprog(np.zeros(self.null.shape[1]), A_ub=a, b_ub=b, bounds=(None, None), method="highs")
        return u + self.null @ res.x if res.status == 0 else u

    def extremes(self, u, rows: np.ndarray) -> tuple[np.ndarray, list]:
        """(lower, upper) of each row . u over the structural shifts of u within the bounds, and the shifted
        sets where each is reached (on the straight part of the fibre: starts for ``fibre_extent``)."""
        out = np.tile((rows @ u)[:, None], (1, 2))
        if self.null.shape[1] == 0:
            return out, []
        costs = [row @ self.null for row in rows]
        moving = np.array([np.linalg.norm(c) > ROW_SPACE_TOL for c in costs], dtype=bool)
        offsets, shifts = lp_extent(
            [c for c, m in zip(costs, moving) if m], *shift_constraints(self.p, self.null, u)
        )
        out[moving] += offsets
        return out, [u + self.null @ s for s in shifts]

    def slack(self, u) -> float:
        """Largest distance [log10] to the box bounds of any set with the motion of u (structural shifts)."""
        k = self.null.shape[1]
        if k == 0:
            return float(np.min(np.minimum(u - self.lo, self.hi - u)))
        ones = np.ones((len(u), 1))
        a = np.vstack([np.hstack([-self.null, ones]), np.hstack([self.null, ones])])
        b = np.concatenate([u - self.lo, self.hi - u])
        c = np.r_[np.zeros(k), -1.0]
        res = linprog(c, A_ub=a, b_ub=b, bounds=[(None, None)] * (k + 1), method="highs")
        return float(-res.fun) if res.status == 0 else 0.0

    def row_limits(self, row) -> tuple[float, float]:
        """(lowest, highest) offset of row . u from the best fit over the bounds box."""
        lo = np.sum(np.where(row > 0, row * self.lo, row * self.hi)) - row @ self.u0
        hi = np.sum(np.where(row > 0, row * self.hi, row * self.lo)) - row @ self.u0
        return float(lo), float(hi)


def _first_step(space: _Space, g: np.ndarray, limit: float) -> float:
    """Offset where the linearised profile rises by half the threshold (Gauss-Newton spread of g . w)."""
    jw = space.jacobian_w
    if jw is None or not np.all(np.isfinite(jw)):
        return max(PL_FIRST_STEP, limit / 8)
    var = float(g @ np.linalg.pinv(jw.T @ jw) @ g) / float(g @ g) ** 2
    step = np.sqrt(PL_THRESHOLD / 2 * var) if var > 0 else limit / 8
    return float(np.clip(step, PL_FIRST_STEP, max(min(limit / 8, PL_MAX_STEP), PL_FIRST_STEP)))


def profile_row(forward: Forward, space: _Space, row: np.ndarray, floor: float, pool: list):
    """The profile likelihood (a ``LikelihoodProfile``) of one quantity (see the module text); None where
    it does not move the identifiable coordinates. ``pool``: log10 sets already found within the threshold
    (by other profiles), tried as starts where the extrapolated one fails; the sets found here join it."""
    g = space.basis.T @ row
    full = np.vstack([g])
    _, s, vt = np.linalg.svd(full, full_matrices=True)
    rank = int(np.sum(s > 1e-10 * max(s.max(), 1.0)))
    if rank == 0:
        return None
    q = vt[rank:].T  # the coordinates that keep this quantity
    along = np.linalg.pinv(full) @ np.ones(1)  # moves g . w by 1
    walk = _Walk(forward, space, (g, q, along), pool, floor)
    t_lo, t_hi = space.row_limits(row)
    (below, open_lower), (above, open_upper) = (
        walk.side(sign, limit, _first_step(space, g, limit))
        for sign, limit in ((-1.0, -t_lo * (1 - 1e-9)), (1.0, t_hi * (1 - 1e-9)))
    )
    order = np.argsort(walk.t, kind="stable")
    t, chi2, u = (np.array(values)[order] for values in (walk.t, walk.chi2, walk.u))
    return LikelihoodProfile(t, chi2, 10.0**u, -below, above, open_lower, open_upper)


class _Walk:
    """The grid of one profile: every point evaluated (t, chi-square, set), stepping out side by side."""

    def __init__(self, forward, space, coordinates, pool, floor):
        self.g, self.q, self.along = coordinates  # the quantity, the free coordinates, the step along it
        self.fun, self.space, self.pool, self.floor = _fun(forward, space.p), space, pool, floor
        self.jq = space.jacobian(forward) @ self.q if self.q.shape[1] else None
        self.t, self.chi2, self.u = [0.0], [floor], [space.u0]

    def side(self, sign: float, limit: float, step: float) -> tuple[float, bool]:
        """(last offset within the threshold, whether the data leave that side open) stepping out: open when
        the bound of the quantity is reached within the threshold, when the valley runs into the bounds of
        the others (no set within the bounds found, or the last set within the threshold lies within PL_EDGE
        of them), or when the profile had not risen (PL_RISE) before the step that left the threshold."""
        zs, ts, u_in, c_in = [np.zeros(self.q.shape[1])], [0.0], self.space.u0, self.chi2[0]
        t_in, reached, halvings, grow = 0.0, limit <= 0, 0, 2.0
        while not reached:
            t = min(t_in + step, limit)
            u, c, z = self.attempt(
                sign * t, _predict(zs, ts, t, self.jq, self.space, self.along * sign * t), zs[-1]
            )
            self.t.append(sign * t), self.chi2.append(c), self.u.append(u)
            if not c <= self.floor + PL_THRESHOLD:
                if halvings < PL_HALVINGS:  # a curved valley may have been overshot: shorter steps on
                    step, halvings, grow = step / 2, halvings + 1, 1.0
                    continue
                flat = c_in < self.floor + PL_RISE * PL_THRESHOLD  # had not risen: no data bound
                return t_in, bool(np.isinf(c) or flat or self.space.slack(u_in) < PL_EDGE)
            self.floor = min(self.floor, c)
            self.pool.append(u)
            zs.append(z), ts.append(t)
            t_in, reached, step, u_in, c_in = t, t >= limit, min(grow * step, PL_MAX_STEP), u, c
        return t_in, reached

    def attempt(self, t: float, predicted, previous):
        """The best of the re-minimisations from the extrapolated start, else from the previous point's, else
        from the nearest pooled set; stops at the first within the threshold."""
        w_fixed = self.along * t
        best = self.point(w_fixed, predicted)
        for start in (previous, *self.from_pool(w_fixed)):
            if best[1] <= self.floor + PL_THRESHOLD or start is None:
                break
            if start is previous and np.allclose(previous, predicted):
                continue
            best = min(best, self.point(w_fixed, start), key=lambda x: x[1])
        return best

    def point(self, w_fixed, z0):
        return _minimise(
            self.fun, self.space, w_fixed, self.q, z0, self.floor + PL_CLOSE * PL_THRESHOLD, PL_NFEV
        )

    def from_pool(self, w_fixed) -> list:
        """Start (z) at the pooled set closest to this value of the quantity, if one is within PL_MAX_STEP."""
        if not self.pool or self.q.shape[1] == 0:
            return []
        ws = (np.array(self.pool) - self.space.u0) @ self.space.basis
        gap = np.abs(ws @ self.g - w_fixed @ self.g)
        near = int(np.argmin(gap))
        return [self.q.T @ ws[near]] if gap[near] <= PL_MAX_STEP else []


def _predict(zs, ts, t, jq, space: _Space, w_fixed) -> np.ndarray:
    """Start of the re-minimisation at offset t: the last three sets extrapolated quadratically (two:
    linearly), else the Gauss-Newton step from the best fit (the valley's tangent)."""
    if len(zs) >= 3:
        return np.array([np.polyval(np.polyfit(ts[-3:], c, 2), t) for c in np.array(zs[-3:]).T]).reshape(-1)
    if len(zs) >= 2:
        return zs[-1] + (zs[-1] - zs[-2]) * (t - ts[-1]) / (ts[-1] - ts[-2])
    if jq is None or not np.all(np.isfinite(jq)):
        return zs[-1]
    jw_fixed = space.jacobian_w @ w_fixed
    return np.linalg.lstsq(jq, -(space.r0 + jw_fixed), rcond=None)[0]


def _minimise(fun, space: _Space, w_fixed, q, z0, target: float, nfev: int):
    """(log10 set, chi-square, z) of the smallest chi-square found over w = w_fixed + q z, stopping at the
    first set within ``target``."""

    def residuals(z):
        r = fun(space.feasible(w_fixed + q @ z))
        if float(r @ r) <= target:
            raise _Within(np.array(z, dtype=float))
        return r

    try:
        if q.shape[1] == 0:
            residuals(np.zeros(0))
            z = np.zeros(0)
        else:
            z = least_squares(residuals, z0, method="trf", diff_step=JACOBIAN_STEP, max_nfev=nfev).x
    except _Within as hit:
        z = hit.z
    u = space.feasible(w_fixed + q @ z)
    r = fun(u)
    chi2 = float(r @ r)
    return u, (chi2 if space.p.in_bounds(_power10(u)) else np.inf), z


def profile_identify(forward: Forward, free_values, structure: tuple) -> ProfileIdentification:
    """Profile every quantity the runs' ``structure`` leaves identifiable (``structural_rows``) at a best
    fit; the dimensions are the equations' (exact)."""
    p = forward.problem
    u0 = np.log10(np.asarray(free_values, dtype=float))
    space = _Space(p, u0)
    r0 = forward.residuals(10.0**u0)
    floor = float(r0 @ r0)
    profiles, pool = {}, []
    for name, row in structural_rows(p, structure).items():
        pr = profile_row(forward, space, row, floor, pool)
        if pr is not None:
            profiles[name] = pr
            floor = min(floor, float(np.min(pr.chi2)))
    return ProfileIdentification(profiles, runs_rank(structure, tuple(p.free)), floor, structure)


def _ends(pr: LikelihoodProfile, floor: float) -> list:
    """log10 sets at the two ends of a profile's interval within the threshold."""
    keep = (pr.t >= pr.t_lower) & (pr.t <= pr.t_upper) & (pr.chi2 <= floor + PL_THRESHOLD)
    if not np.any(keep):
        return []
    t, u = pr.t[keep], np.log10(pr.points[keep])
    return [u[int(np.argmin(t))], u[int(np.argmax(t))]]


@dataclass(frozen=True)
class QuantityRange:
    """What the data say about one quantity: its range over the sets within the threshold."""

    lower: float
    upper: float
    open_lower: bool
    open_upper: bool
    """The range reaches the bounds on that side within the threshold (the data do not bound it there)."""
    profiled: bool
    identifiable: bool
    """Profiled, and its profile exceeds the threshold on both sides within the bounds."""


def quantity_ranges(problem: Problem, free_values, pid: ProfileIdentification, rows: dict) -> dict:
    """Name -> QuantityRange of each row (a free parameter or a combination, in log10 exponents over the
    free parameters): the extent over the fibre (``structure.fibre_extent``) through the best fit and each
    profile's two ends (the sets between lie on the same valley), and over the structural shifts of those
    within the bounds; open where that reaches the row's limit over the bounds box or where its own profile
    ended on the bounds."""
    names = list(rows)
    matrix = np.array([rows[n] for n in names], dtype=float).reshape(len(names), -1)
    u0 = np.log10(np.asarray(free_values, dtype=float))
    space = _Space(problem, u0)
    lower, upper = problem.log_bounds
    ext, fibre = [], []
    for u in [u0] + [u for pr in pid.profiles.values() for u in _ends(pr, pid.floor)]:
        shifts, corners = space.extremes(u, matrix)
        ext.append(shifts)
        fibre.append(
            fibre_extent(
                pid.structure, tuple(problem.free), u, matrix, lower, upper, problem.plateau_pair, corners
            )
        )
    ext, fibre = np.array(ext), np.array(fibre)  # points x rows x 2
    ext = np.stack([np.fmin(ext[..., 0], fibre[..., 0]), np.fmax(ext[..., 1], fibre[..., 1])], axis=-1)
    base = matrix @ u0
    ext = np.column_stack([np.nanmin(ext[:, :, 0], axis=0) - base, np.nanmax(ext[:, :, 1], axis=0) - base])
    value = 10.0 ** (matrix @ u0)
    out = {}
    for i, name in enumerate(names):
        lo, hi = space.row_limits(matrix[i])
        pr = pid.profiles.get(name)
        open_lo = bool(ext[i, 0] <= lo + 1e-6 or (pr is not None and pr.open_lower))
        open_hi = bool(ext[i, 1] >= hi - 1e-6 or (pr is not None and pr.open_upper))
        out[name] = QuantityRange(
            lower=float(value[i] * 10.0 ** ext[i, 0]),
            upper=float(value[i] * 10.0 ** ext[i, 1]),
            open_lower=open_lo,
            open_upper=open_hi,
            profiled=pr is not None,
            identifiable=bool(pr is not None and pr.identifiable and not (open_lo or open_hi)),
        )
    return out
