"""Minimal conflicting subsets of a figure's reported numbers.

A subset S of the reported numbers *conflicts* when no parameter set within the bounds puts every number of
S within its reading precision (|residual| <= 1). It is *minimal* when no proper subset conflicts: those are
the numbers of the figure that contradict each other, whatever the rest says.

Search, by increasing size up to a cap:

* a subset containing a conflicting subset already found is not minimal and is skipped;
* a subset is *satisfied* (not conflicting) when a *witness* puts all its numbers within precision; every
  parameter set evaluated here is kept as a witness (the figure's best fit and stated set to begin with, then
  every point the subset fits visit), so most subsets cost no run at all;
* any other subset is fitted alone: least squares on its numbers only (log10 of the free parameters within
  their bounds, started from the witness with the smallest chi-square on it, ``max_nfev`` iterations). If the
  fit's worst residual stays above 1 the subset conflicts, with that worst residual as its margin.

"Conflicting" therefore means the fit found nothing within precision: an optimiser that misses a narrow
consistent pocket would list a subset that is not truly conflicting. The cap on the subset size bounds the
cost (the number of subsets grows as n choose k); a figure whose search stopped at the cap says so.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import numpy as np
from scipy.optimize import least_squares

from .fit import INFEASIBLE_RESIDUAL, _fun
from .forward import Forward

#: Largest subset size searched. Fig. 2 has 12 numbers: sizes <= 3 are 298 subsets, <= 4 would be 793.
CONFLICT_MAX_SIZE = 3
#: Least-squares iterations of each subset fit. The default build's conflict sets are identical with 10, 20
#: and 40 (benchmarks/bench_inverse.py --conflict-check measures it); 10 is the cheapest.
CONFLICT_NFEV = 10


@dataclass(frozen=True)
class Conflict:
    members: tuple
    """Indices of the conflicting numbers in the problem's observations."""
    worst: float
    """Smallest worst |residual| over the subset that any fit reached (> 1; inf: never produced)."""


@dataclass(frozen=True)
class ConflictSearch:
    conflicts: tuple
    max_size: int
    numbers: int
    subsets_fitted: int
    witness: np.ndarray | None
    """A free-parameter set putting every number of the figure within precision (the one of smallest
    chi-square seen), or None: when found, the figure is consistent after all."""

    @property
    def complete(self) -> bool:
        """Every subset size was searched (the cap is not below the number of numbers)."""
        return self.max_size >= self.numbers


class _Satisfied(Exception):
    """Raised inside a subset fit when a point puts every number of the subset within precision."""


class _Witnesses:
    """Residual vectors (all numbers; NaN where a number is not produced) of every parameter set seen, and
    the sets themselves (log10). A set witnesses a subset when it puts the subset's numbers within
    precision, whatever it does to the others."""

    def __init__(self, n: int):
        self.r = np.empty((0, n))
        self.u = []

    def add(self, u, r):
        r = np.asarray(r, dtype=float)
        if np.any(np.isfinite(r)):
            self.r = np.vstack([self.r, r])
            self.u.append(np.array(u, dtype=float))

    def _abs(self, subset) -> np.ndarray:
        a = np.abs(self.r[:, list(subset)])
        return np.where(np.isfinite(a), a, np.inf)

    def satisfies(self, subset) -> bool:
        return bool(np.any(np.all(self._abs(subset) <= 1.0, axis=1)))

    def closest(self, subset) -> float | None:
        """Smallest worst |residual| over the subset any witness reached."""
        if not len(self.r):
            return None
        return float(np.min(np.max(self._abs(subset), axis=1)))

    def full(self) -> np.ndarray | None:
        """The set of smallest chi-square among those putting every number within precision."""
        ok = np.all(self._abs(range(self.r.shape[1])) <= 1.0, axis=1)
        if not ok.any():
            return None
        chi2 = np.where(ok, np.sum(np.nan_to_num(self.r, nan=np.inf) ** 2, axis=1), np.inf)
        return 10.0 ** self.u[int(np.argmin(chi2))]

    def start(self, subset) -> np.ndarray | None:
        """The set of smallest chi-square on the subset (None: no set produces all its numbers)."""
        cost = np.sum(self._abs(subset) ** 2, axis=1)
        return self.u[int(np.argmin(cost))] if np.isfinite(cost).any() else None


def minimal_conflicts(
    forward: Forward,
    seeds,
    max_size: int = CONFLICT_MAX_SIZE,
    max_nfev: int = CONFLICT_NFEV,
) -> ConflictSearch:
    """Minimal conflicting subsets of ``forward.problem``'s numbers (see the module text).

    ``seeds``: free-parameter sets to start the witnesses with (e.g. the best fit and the stated set).
    """
    p = forward.problem
    n = len(p.observations)
    lo, hi = p.log_bounds
    inner = lo + 1e-6 * (hi - lo), hi - 1e-6 * (hi - lo)
    witnesses = _Witnesses(n)
    for s in seeds:
        s = np.asarray(s, dtype=float)
        if p.in_bounds(s):
            witnesses.add(np.log10(s), forward.residuals(s))
    fun = _fun(forward, p)

    def recorded(u, idx):
        r = fun(u)
        witnesses.add(u, np.where(np.abs(r) < INFEASIBLE_RESIDUAL, r, np.nan))  # not produced: NaN
        if np.all(np.abs(r[idx]) <= 1.0):
            raise _Satisfied  # a witness: the subset does not conflict, no need to fit on
        return r[idx]

    found: list[Conflict] = []
    fitted = 0
    for k in range(1, min(max_size, n) + 1):
        for subset in combinations(range(n), k):
            if any(set(c.members) <= set(subset) for c in found) or witnesses.satisfies(subset):
                continue
            start = witnesses.start(subset)
            idx = list(subset)
            fitted += 1
            try:
                res = least_squares(
                    lambda u, idx=idx: recorded(u, idx),
                    np.clip(np.log10(p.stated_free) if start is None else start, *inner),
                    bounds=(lo, hi),
                    method="trf",
                    diff_step=1e-3,
                    max_nfev=max_nfev,
                )
            except _Satisfied:
                continue
            worst = min(witnesses.closest(subset) or np.inf, float(np.max(np.abs(res.fun))))
            found.append(Conflict(subset, worst if worst < INFEASIBLE_RESIDUAL else np.inf))
    return ConflictSearch(
        conflicts=tuple(found),
        max_size=int(max_size),
        numbers=n,
        subsets_fitted=fitted,
        witness=witnesses.full(),
    )
