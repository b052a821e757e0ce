"""Best fit (scipy.optimize.least_squares, seeded multi-start) and the consistent region (emcee, seeded).

Coordinates. The optimiser works in log10 of the free parameters within their bounds; the sampler in the
identifiable coordinates w of the problem (see ``problem``), whose parameter set is the one closest to the
stated set. Prior: uniform in w where that set lies within the bounds (and, with a plateau, keeps the
coefficient non-negative). Likelihood: Gaussian, each reported number's standard deviation its reading
precision (the claim's tolerance); an infeasible parameter set has likelihood zero (log -inf).

Verdict. A figure's numbers are *consistent* under a family when the best fit puts every number within its
reading precision (|residual| <= 1), otherwise *inconsistent*.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import emcee
import numpy as np
from scipy.optimize import least_squares

from .forward import Forward
from .problem import Problem

#: Residual given to the optimiser for a number an infeasible parameter set cannot produce (and the bound
#: of every residual the optimiser sees).
INFEASIBLE_RESIDUAL = 100.0
#: Below this 1 - h_ii a leave-one-out residual is undefined (the number alone fixes a direction).
LOO_MIN_LEVER = 0.05
#: Seeded random points scouted per extra least-squares start.
SCOUTS_PER_START = 8


@dataclass
class BestFit:
    free_values: np.ndarray
    """The best-fitting set closest to the stated one (same motion as the optimiser's point)."""
    residuals: np.ndarray
    jacobian: np.ndarray
    """d residual / d log10(free parameter) at the optimum (n_numbers x n_free)."""

    @property
    def chi2(self) -> float:
        r = self.residuals
        return float(r @ r) if np.all(np.isfinite(r)) else np.inf

    @property
    def worst(self) -> float:
        return float(np.max(np.abs(self.residuals))) if np.all(np.isfinite(self.residuals)) else np.inf

    @property
    def consistent(self) -> bool:
        return bool(self.worst <= 1.0)


@dataclass
class Region:
    samples_free: np.ndarray
    log_likelihood: np.ndarray
    acceptance: np.ndarray
    autocorr_time: np.ndarray
    steps: int
    infeasible_fraction: float
    laplace_sd_log10: np.ndarray
    """Gauss-Newton (Laplace) standard deviation of log10 of each free parameter at the best fit."""

    @property
    def converged(self) -> bool:
        """emcee's rule of thumb: the chain is at least 50 autocorrelation times long."""
        return bool(np.all(np.isfinite(self.autocorr_time)) and self.steps >= 50 * np.max(self.autocorr_time))

    @property
    def sd_log10(self) -> np.ndarray:
        """Posterior spread of log10 of each free parameter: sampled if converged, else the Laplace one."""
        if self.converged and len(self.samples_free) > 1:
            return np.std(np.log10(self.samples_free), axis=0)
        return self.laplace_sd_log10


def _fun(forward: Forward, problem: Problem):
    def fun(u):
        values = _power10(u)
        if not problem.in_bounds(values):
            return np.full(len(problem.observations), INFEASIBLE_RESIDUAL)
        r = forward.residuals(values)  # clipped: a run growing without bound must not overflow the solver
        return np.clip(
            np.where(np.isfinite(r), r, INFEASIBLE_RESIDUAL), -INFEASIBLE_RESIDUAL, INFEASIBLE_RESIDUAL
        )

    return fun


def _power10(u) -> np.ndarray:
    """10**u, inf where a step far outside the bounds overflows (the bounds check then rejects it)."""
    with np.errstate(over="ignore"):
        return 10.0**u


def best_fit(forward: Forward, starts: int, max_nfev: int, seed: int, x0=None, candidates=()) -> BestFit:
    """Seeded multi-start least squares; the first start is the stated set (or ``x0``), the others the best
    of ``candidates`` (free-parameter sets, e.g. the per-figure fits) or else of a seeded uniform batch."""
    p = forward.problem
    lo, hi = p.log_bounds
    rng = np.random.default_rng(seed)
    first = np.log10(p.stated_free if x0 is None else np.asarray(x0, dtype=float))
    inner = lo + 1e-6 * (hi - lo), hi - 1e-6 * (hi - lo)
    fun = _fun(forward, p)
    x0s = [np.clip(first, *inner)]
    if starts > 1:  # the other starts: the best of the candidates (e.g. other fits) or of a seeded batch
        batch = [np.clip(np.log10(np.asarray(c, dtype=float)), *inner) for c in candidates]
        if not batch:
            batch = list(rng.uniform(*inner, size=(SCOUTS_PER_START * (starts - 1), len(lo))))
        cost = np.array([float(np.sum(fun(u) ** 2)) for u in batch])
        x0s += [batch[i] for i in np.argsort(cost, kind="stable")[: starts - 1]]
    fits = (
        least_squares(fun, x, bounds=(lo, hi), method="trf", diff_step=1e-3, max_nfev=max_nfev) for x in x0s
    )
    best = min(fits, key=lambda res: res.cost)  # the first of equal costs
    found = 10.0**best.x
    closest = p.closest_equivalent(found)
    values = closest if p.in_bounds(closest) else found
    return BestFit(values, forward.residuals(values), np.asarray(best.jac, dtype=float))


def fit_at(forward: Forward, free_values, diff_step: float = 1e-3) -> BestFit:
    """A BestFit at a given set (e.g. a witness of consistency found after the least-squares fit), its
    Jacobian by central differences in log10 with the optimiser's relative step."""
    values = np.asarray(free_values, dtype=float)
    u = np.log10(values)
    fun = _fun(forward, forward.problem)
    cols = []
    for j in range(len(u)):
        e = np.zeros_like(u)
        e[j] = diff_step * max(abs(u[j]), 1.0)
        cols.append((fun(u + e) - fun(u - e)) / (2 * e[j]))
    return BestFit(values, forward.residuals(values), np.array(cols).T)


def prior_precision(problem: Problem) -> float:
    """1 / variance of a uniform prior over the mean log10 width of the bounds (regularises flat
    directions)."""
    lo, hi = problem.log_bounds
    return float(12.0 / np.mean((hi - lo) ** 2))


def laplace_cov_w(problem: Problem, jacobian: np.ndarray) -> np.ndarray:
    """Gauss-Newton (Laplace) covariance of the identifiable coordinates w at a best fit (with the weak prior
    of ``prior_precision``)."""
    basis = problem.identifiable_basis()
    jw = jacobian @ basis
    return np.linalg.inv(jw.T @ jw + prior_precision(problem) * np.eye(basis.shape[1]))


def laplace_sd(problem: Problem, jacobian: np.ndarray) -> np.ndarray:
    """Gauss-Newton standard deviation of log10 free parameters in the identifiable directions."""
    basis = problem.identifiable_basis()
    cov_w = laplace_cov_w(problem, jacobian)
    return np.sqrt(np.clip(np.diag(basis @ cov_w @ basis.T), 0.0, None))


def sample_region(forward: Forward, fit: BestFit, walkers: int, steps: int, seed: int) -> Region:
    """emcee from the best fit's Laplace approximation, seeded; the first half of the chain is burn-in."""
    p = forward.problem
    ndim = p.identifiable_basis().shape[1]
    if walkers < 2 * ndim:
        raise ValueError(f"inverse.settings.walkers: {walkers} < 2 x {ndim} identifiable dimensions")
    rng = np.random.default_rng(seed)
    w0 = p.to_coordinates(fit.free_values)

    def log_prob(w):
        values = p.from_coordinates(w)
        return forward.log_likelihood(values) if p.in_bounds(values) else -np.inf

    # start from the Laplace approximation (capped), so the walkers begin spread along weak directions
    spread = np.clip(np.sqrt(np.diag(laplace_cov_w(p, fit.jacobian))), 1e-3, 0.3)
    start = []
    for _ in range(walkers):
        scale = spread
        for _ in range(20):  # a start must be feasible; shrink toward the best fit until it is
            w = w0 + scale * rng.standard_normal(ndim)
            if np.isfinite(log_prob(w)):
                break
            scale *= 0.5
        start.append(w)
    sampler = emcee.EnsembleSampler(walkers, ndim, log_prob)
    sampler.random_state = np.random.RandomState(seed).get_state()
    n0, inf0 = forward.evaluations, forward.infeasible
    # the starts are independent Gaussian draws; a start shrunk toward the best fit (to be feasible) may make
    # the ensemble nearly degenerate, which emcee's start check rejects, though the stretch move recovers
    sampler.run_mcmc(np.array(start), steps, progress=False, skip_initial_state_check=True)
    burn = steps // 2
    chain = sampler.get_chain(discard=burn, flat=True)
    logp = sampler.get_log_prob(discard=burn, flat=True)
    # a coordinate whose chain never moved has no autocorrelation (0/0): NaN, i.e. not converged
    with np.errstate(invalid="ignore", divide="ignore"):
        tau = sampler.get_autocorr_time(tol=0, quiet=True) if steps >= 4 else np.full(ndim, np.nan)
    free = np.array([p.from_coordinates(w) for w in chain]).reshape(-1, len(p.free))
    used = max(forward.evaluations - n0, 1)
    return Region(
        samples_free=free,
        log_likelihood=logp,
        acceptance=np.asarray(sampler.acceptance_fraction, dtype=float),
        autocorr_time=np.asarray(tau, dtype=float),
        steps=steps,
        infeasible_fraction=(forward.infeasible - inf0) / used,
        laplace_sd_log10=laplace_sd(p, fit.jacobian),
    )


def loo_linear(problem: Problem, fit: BestFit) -> np.ndarray:
    """Leave-one-out residuals, linearised at the best fit: r_i / (1 - h_ii) (PRESS residuals).

    h is the hat matrix of the whitened Gauss-Newton problem in the identifiable coordinates (with the weak
    prior of ``prior_precision``); a number that alone fixes a direction (1 - h_ii < LOO_MIN_LEVER) gets NaN:
    left out, nothing predicts it, and the linearisation would divide by round-off.
    """
    jw = fit.jacobian @ problem.identifiable_basis()
    h = jw @ laplace_cov_w(problem, fit.jacobian) @ jw.T
    lever = 1.0 - np.diag(h)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(lever > LOO_MIN_LEVER, fit.residuals / lever, np.nan)


def loo_refit(forward: Forward, fit: BestFit, max_nfev: int, seed: int) -> np.ndarray:
    """Leave-one-out residuals by refitting without each number, started at the full best fit."""
    p = forward.problem
    out = np.full(len(p.observations), np.nan)
    for i in range(len(p.observations)):
        reduced = replace(p, observations=tuple(o for k, o in enumerate(p.observations) if k != i))
        sub = Forward(reduced, dict(forward.hypothesis))
        refit = best_fit(sub, 1, max_nfev, seed, x0=fit.free_values)
        out[i] = forward.residuals(refit.free_values)[i]
    return out
