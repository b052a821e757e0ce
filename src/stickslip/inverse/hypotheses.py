"""Which misprint explains the reported numbers: single changes of the stated parameters and the
alternatives the text itself allows, each scored on a (joint) problem with every other parameter as stated.

A *single change* scans one free parameter over its bounds (log-spaced), everything else stated; its score is
the number of reported numbers reproduced within their reading precision and the chi-square at the best scan
point. Its spread is the conditional posterior sd of log10 of the parameter on the scan grid (flat prior in
log10), and ``z`` = (best - stated) / that spread in log10 units.

*Named hypotheses* (config ``inverse.hypotheses``): BeltParams values applied to every run (sigma 0.3, the SI
unit reading), the Eq. 4 sigma V_b term, and a kinetic coefficient mu_k = r mu_s scanned over r.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..schema import Hypothesis
from .forward import Forward
from .problem import Problem


@dataclass(frozen=True)
class Score:
    hypothesis: str
    parameter: str
    value: float
    stated: float
    chi2: float
    reproduced: int
    numbers: int
    worst: float
    worst_claim: str
    z: float = np.nan
    description: str = ""

    def row(self, family: str) -> dict:
        return {"family": family, **self.__dict__}


def score(problem: Problem, residuals: np.ndarray) -> dict:
    """chi2, the numbers within precision and of the problem, the worst |residual| and its claim (the first
    number not produced, with chi2 and worst inf, where the set is infeasible)."""
    r = np.asarray(residuals, dtype=float)
    finite = np.isfinite(r)
    feasible = bool(finite.all())
    k = int(np.argmax(np.abs(r))) if feasible else int(np.argmax(~finite))
    return dict(
        chi2=float(r @ r) if feasible else np.inf,
        reproduced=int(np.sum(np.abs(r[finite]) <= 1.0)),
        numbers=len(problem.observations),
        worst=float(abs(r[k])) if feasible else np.inf,
        worst_claim=problem.observations[k].claim,
    )


def _grid_posterior(log_grid: np.ndarray, chi2: np.ndarray) -> tuple[float, float]:
    """Mean and sd of a 1-D posterior exp(-chi2/2) on a log10 grid (flat prior); NaN if nothing feasible."""
    ok = np.isfinite(chi2)
    if not ok.any():
        return np.nan, np.nan
    w = np.zeros_like(chi2)
    w[ok] = np.exp(-0.5 * (chi2[ok] - chi2[ok].min()))
    w /= w.sum()
    mean = float(np.sum(w * log_grid))
    sd = float(np.sqrt(np.sum(w * (log_grid - mean) ** 2)))
    half_step = 0.5 * float(np.mean(np.diff(log_grid))) if len(log_grid) > 1 else np.nan
    return mean, max(sd, half_step / np.sqrt(3.0))  # never narrower than the grid can resolve


def single_changes(problem: Problem, points: int) -> list[Score]:
    """Scan each free parameter alone over its bounds, every other one at its stated value."""
    forward = Forward(problem)
    stated = problem.stated_free
    outside = dict(chi2=np.inf, reproduced=0, numbers=len(problem.observations), worst=np.inf, worst_claim="")
    out = []
    for i, name in enumerate(problem.free):
        lo, hi = problem.bounds[name]
        grid = np.geomspace(lo, hi, points)
        scores = []
        for value in grid:
            values = stated.copy()
            values[i] = value
            scores.append(score(problem, forward.residuals(values)) if problem.in_bounds(values) else outside)
        chi2 = np.array([s["chi2"] for s in scores])
        k = int(np.argmin(chi2)) if np.isfinite(chi2).any() else 0
        _, sd = _grid_posterior(np.log10(grid), chi2)
        z = (np.log10(grid[k]) - np.log10(stated[i])) / sd if np.isfinite(sd) and sd > 0 else np.nan
        description = f"only {name} changed, scanned over the bounds"
        out.append(
            Score(
                "single_change",
                name,
                float(grid[k]),
                float(stated[i]),
                **scores[k],
                z=float(z),
                description=description,
            )
        )
    return out


def stated_score(problem: Problem, hypothesis: dict | None = None, label="stated", description="") -> Score:
    forward = Forward(problem, dict(hypothesis or {}))
    s = score(problem, forward.residuals(problem.stated_free))
    return Score(label, "", np.nan, np.nan, **s, description=description or "every parameter as stated")


def named_hypotheses(problem: Problem, hypotheses: dict[str, Hypothesis], points: int) -> list[Score]:
    """The text's own alternatives (config inverse.hypotheses), each with every other parameter stated; a
    hypothesis is listed under the first value it sets (in the order of ``Hypothesis``'s fields)."""
    out = []
    for label, hypothesis in hypotheses.items():
        spec = hypothesis.model_dump(exclude_none=True, exclude={"description", "mu_k_ratio"})
        description, ratio = hypothesis.description, hypothesis.mu_k_ratio
        if ratio is not None:
            grid = np.linspace(ratio.min, ratio.max, points)
            scores = [
                stated_score(problem, {**spec, "mu_k_ratio": float(r)}, label, description) for r in grid
            ]
            k = int(np.argmin([s.chi2 for s in scores]))
            out.append(replace(scores[k], parameter="mu_k/mu_s", value=float(grid[k]), stated=1.0))
            continue
        s = stated_score(problem, spec, label, description)
        param = next(iter(spec), "")
        value = spec.get(param, np.nan)
        value = float(value) if isinstance(value, (int, float)) else np.nan
        out.append(replace(s, parameter=param, value=value))
    return out


def ranking(problem: Problem, best_free: np.ndarray, sd_log10: np.ndarray) -> list[dict]:
    """Each stated parameter: inferred (joint best fit) vs stated in units of the posterior spread (log10)."""
    rows = []
    for i, name in enumerate(problem.free):
        z = (
            (np.log10(best_free[i]) - np.log10(problem.stated_free[i])) / sd_log10[i]
            if sd_log10[i] > 0
            else np.nan
        )
        rows.append(
            {
                "parameter": name,
                "stated": float(problem.stated_free[i]),
                "inferred": float(best_free[i]),
                "sd_log10": float(sd_log10[i]),
                "z": float(z),
            }
        )
    return sorted(rows, key=lambda r: -abs(r["z"]) if np.isfinite(r["z"]) else 0.0)
