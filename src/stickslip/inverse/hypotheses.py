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

from dataclasses import dataclass

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


def score(problem: Problem, residuals: np.ndarray) -> tuple[float, int, float, str]:
    """(chi2, numbers within precision, worst |residual|, its claim); infeasible -> inf, 0."""
    r = np.asarray(residuals, dtype=float)
    if not np.all(np.isfinite(r)):
        bad = int(np.argmax(~np.isfinite(r)))
        return np.inf, int(np.sum(np.abs(r[np.isfinite(r)]) <= 1.0)), np.inf, problem.observations[bad].claim
    k = int(np.argmax(np.abs(r)))
    return float(r @ r), int(np.sum(np.abs(r) <= 1.0)), float(abs(r[k])), problem.observations[k].claim


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


def single_changes(problem: Problem, points: int, hypothesis: dict | None = None) -> list[Score]:
    """Scan each free parameter alone over its bounds, every other one at its stated value."""
    forward = Forward(problem, dict(hypothesis or {}))
    stated = problem.stated_free
    out = []
    for i, name in enumerate(problem.free):
        lo, hi = problem.bounds[name]
        grid = np.geomspace(lo, hi, points)
        chi2, scores = [], []
        for value in grid:
            values = stated.copy()
            values[i] = value
            s = (
                score(problem, forward.residuals(values))
                if problem.in_bounds(values)
                else (np.inf, 0, np.inf, "")
            )
            chi2.append(s[0])
            scores.append(s)
        chi2 = np.array(chi2)
        k = int(np.argmin(chi2)) if np.isfinite(chi2).any() else 0
        _, sd = _grid_posterior(np.log10(grid), chi2)
        c, n_ok, worst, claim = scores[k]
        z = (np.log10(grid[k]) - np.log10(stated[i])) / sd if np.isfinite(sd) and sd > 0 else np.nan
        out.append(
            Score(
                "single_change",
                name,
                float(grid[k]),
                float(stated[i]),
                c,
                n_ok,
                len(problem.observations),
                worst,
                claim,
                float(z),
                f"only {name} changed, scanned over the bounds",
            )
        )
    return out


def stated_score(problem: Problem, hypothesis: dict | None = None, label="stated", description="") -> Score:
    forward = Forward(problem, dict(hypothesis or {}))
    c, n_ok, worst, claim = score(problem, forward.residuals(problem.stated_free))
    return Score(
        label,
        "",
        np.nan,
        np.nan,
        c,
        n_ok,
        len(problem.observations),
        worst,
        claim,
        description=description or "every parameter as stated",
    )


def named_hypotheses(problem: Problem, hypotheses: dict[str, Hypothesis], points: int) -> list[Score]:
    """The text's own alternatives (config inverse.hypotheses), each with every other parameter stated; a
    hypothesis is listed under the first value it sets (in the order of ``Hypothesis``'s fields)."""
    out = []
    for label, hypothesis in hypotheses.items():
        spec = hypothesis.model_dump(exclude_none=True, exclude={"description", "mu_k_ratio"})
        description, ratio = hypothesis.description, hypothesis.mu_k_ratio
        if ratio is not None:
            grid = np.linspace(ratio.min, ratio.max, points)
            forward = Forward(problem, {})
            results = []
            for r in grid:
                forward.hypothesis = {**spec, "mu_k_ratio": float(r)}
                results.append(score(problem, forward.residuals(problem.stated_free)))
            k = int(np.argmin([s[0] for s in results]))
            c, n_ok, worst, claim = results[k]
            out.append(
                Score(
                    label,
                    "mu_k/mu_s",
                    float(grid[k]),
                    1.0,
                    c,
                    n_ok,
                    len(problem.observations),
                    worst,
                    claim,
                    description=description,
                )
            )
            continue
        s = stated_score(problem, spec, label, description)
        param = next(iter(spec), "")
        value = spec.get(param, np.nan)
        out.append(
            Score(
                label,
                param,
                float(value) if isinstance(value, (int, float)) else np.nan,
                np.nan,
                s.chi2,
                s.reproduced,
                s.numbers,
                s.worst,
                s.worst_claim,
                description=description,
            )
        )
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
