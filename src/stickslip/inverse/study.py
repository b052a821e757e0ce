"""The whole inverse study: per figure and family a best fit and a sampled region, the joint fit with its
leave-one-out residuals, the misprint scores; results as xarray datasets and table rows.

Every dataset is labelled a FIT: it sits beside the claims table (the forward replication with the stated
parameters) and changes none of its pins.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ..schema import Inverse, InverseJob, InverseSettings
from .conflicts import CONFLICT_NFEV, minimal_conflicts
from .dataset import COMBINATION_KEYS, FamilyFit, figure_dataset, open_flag
from .fit import best_fit, fit_at, laplace_sd, loo_linear, loo_refit, sample_region
from .forward import Forward
from .hypotheses import named_hypotheses, ranking, single_changes, stated_score
from .identify import identify
from .problem import COMBINATIONS, Problem, build_problem
from .profile import PL_CLOSE, PL_THRESHOLD, profile_identify
from .structure import problem_structure


def fit_problem(
    problem: Problem, settings: InverseSettings, steps: int, loo=False, candidates=(), conflicts=True
) -> FamilyFit:
    """Best fit, region, minimal conflicting subsets (if inconsistent and ``conflicts``), identifiable
    dimensions and (optionally) leave-one-out residuals of one problem.

    A conflict search that finds a set putting every number within precision overturns the least-squares
    verdict: the fit is then that set (``fit_source`` "conflict search"), and the figure is consistent.
    """
    t0 = time.process_time()
    forward = Forward(problem)
    seed = settings.seed
    fit = best_fit(forward, settings.starts, settings.max_nfev, seed, candidates=candidates)
    sampled = steps > 0 and np.isfinite(fit.chi2)  # an infeasible best fit has no region to sample from
    region = sample_region(forward, fit, settings.walkers, steps, seed) if sampled else None
    search, source = None, "least squares"
    if conflicts and not fit.consistent:
        seeds = [fit.free_values, problem.stated_free] + (list(region.samples_free) if region else [])
        # a subset fit gets at most twice a full fit's iterations: the default build's CONFLICT_NFEV, fewer in
        # a build whose fits are token ones (CI size)
        nfev = min(CONFLICT_NFEV, 2 * settings.max_nfev)
        search = minimal_conflicts(forward, seeds, max_nfev=nfev)
        if search.witness is not None:
            closest = problem.closest_equivalent(search.witness)
            fit = fit_at(forward, closest if problem.in_bounds(closest) else search.witness)
            source = "conflict search"
    # the profile likelihood for a figure; the joint problem (32 numbers, a run costs 6x a figure's) keeps
    # the straight-line analysis only, as does a figure the settings leave out (the CI-size configuration
    # profiles one figure, to test the path); the profiles run over what the structure (derived from the
    # equations of the phases the fit visits) leaves identifiable only
    chosen = settings.profile
    profiled = (
        np.isfinite(fit.chi2) and problem.name != "joint" and (chosen is None or problem.name in chosen)
    )
    structure = problem_structure(problem, fit.free_values) if np.isfinite(fit.chi2) else (np.nan, (), ())
    profile = profile_identify(forward, fit.free_values, structure[2]) if profiled else None
    # every fit ends at its minimum: restarted from the deepest point any profile reached (else from itself),
    # and profiled again where that lowers it by more than REPROFILE_DROP
    restarts, nfev = 0, MINIMUM_NFEV_FACTOR * settings.max_nfev
    for round_ in range(MINIMUM_ROUNDS + 1 if profile is not None else 0):
        deeper = profile.floor < fit.chi2 - MINIMUM_TOL
        start = deepest_point(profile) if deeper else fit.free_values
        restarted = lower_of(fit, best_fit(forward, 1, nfev, seed, x0=start))
        drop = fit.chi2 - restarted.chi2
        if restarted is not fit:
            fit, restarts = restarted, restarts + int(deeper)
            structure = problem_structure(problem, fit.free_values)
        if not drop > REPROFILE_DROP or round_ == MINIMUM_ROUNDS:
            break
        profile = profile_identify(forward, fit.free_values, structure[2])
    if profile is None and np.isfinite(fit.chi2):  # no profile to restart from: converge from the fit itself
        fit = lower_of(fit, best_fit(forward, 1, nfev, seed, x0=fit.free_values))
    if restarts:
        source += ", restarted at a deeper profile point" + (f" ({restarts} rounds)" if restarts > 1 else "")
    # the straight-line analysis, once, at the fit the profiles end at
    ident = identify(forward, fit.free_values) if np.isfinite(fit.chi2) else None
    # leave-one-out: the joint problem as configured, a single figure always linearised (cheap)
    if loo and settings.loo == "refit":
        loo_r = loo_refit(forward, fit, settings.refit_nfev, seed)
    else:
        loo_r = loo_linear(problem, fit) if np.all(np.isfinite(fit.jacobian)) else None
    stated_r = forward.residuals(problem.stated_free)
    return FamilyFit(
        problem=problem,
        fit=fit,
        region=region,
        loo=loo_r,
        loo_method=settings.loo if loo else "linear",
        stated_residuals=stated_r,
        residual_noise=residual_noise(problem, fit.free_values) if np.isfinite(fit.chi2) else np.nan,
        conflicts=search,
        identification=ident,
        profile=profile,
        structural_dimensions=structure[0],
        phases=structure[1],
        structure=structure[2],
        fit_source=source,
        forward=forward,
        cpu=time.process_time() - t0,
    )


#: Restarts of a fit from a profile point deeper than it (each then profiled again).
MINIMUM_ROUNDS = 3
#: A profile point this much below the fit's chi-square restarts the fit: far above the residuals' numerical
#: noise (a few 1e-3 per number, ``residual_noise``), far below the profiles' threshold (3.84).
MINIMUM_TOL = 0.05
#: A restart that lowers chi-square by more than this profiles again: the resolution at which a profile judges
#: its own points (``profile.PL_CLOSE`` of the threshold); below it the profiles already describe the valley.
REPROFILE_DROP = PL_CLOSE * PL_THRESHOLD
#: Least-squares iterations of a restart, in units of the first fit's (``max_nfev``): the default 6 x 4 = 24
#: converges from a nearby point (Figs. 7 and 12 stop improving after 12), where the first fit only has to
#: find the basin; a CI-size build's token fits get token restarts.
MINIMUM_NFEV_FACTOR = 4


def lower_of(fit, other):
    """The fit with the lower chi-square; a consistent fit (every number within precision) is kept unless
    the other is consistent too."""
    if other.chi2 < fit.chi2 and (other.consistent or not fit.consistent):
        return other
    return fit


def deepest_point(pid) -> np.ndarray:
    """The free parameter set of the lowest chi-square any profile reached."""
    deepest = min(pid.profiles.values(), key=lambda pr: float(np.min(pr.chi2)))
    return np.asarray(deepest.points[int(np.argmin(deepest.chi2))], dtype=float)


def residual_noise(problem: Problem, free_values) -> float:
    """Numerical noise of the residuals at a set: the largest change when the sample spacing is halved
    (step halving of the time-series metrics). A verdict or conflict margin below it is not a result."""
    dt = float(problem.run_settings["output_dt"])
    coarse = Forward(problem).residuals(free_values)
    fine = Forward(problem, {"output_dt": dt / 2}).residuals(free_values)
    d = np.abs(fine - coarse)
    return float(np.max(d[np.isfinite(d)])) if np.any(np.isfinite(d)) else np.nan


def number_rows(name: str, results: dict[str, FamilyFit]) -> list[dict]:
    """Each reported number with its unit, precision and the measured value at the best fit, per family."""
    rows = []
    for fam, r in results.items():
        p, fit = r.problem, r.fit
        found = r.conflicts.conflicts if r.conflicts is not None else ()
        members = {i for c in found for i in c.members}
        for i, o in enumerate(p.observations):
            rows.append(
                {
                    "figure": name,
                    "family": fam,
                    "claim": o.claim,
                    "metric": o.metric,
                    "unit": o.unit,
                    "reported": o.value,
                    "reading_precision": o.sd,
                    "measured_best": float(f"{o.value + fit.residuals[i] * o.sd:.6g}"),
                    "residual": round(float(fit.residuals[i]), 3),
                    "residual_stated": round(float(r.stated_residuals[i]), 3),
                    "in_a_conflict": int(i in members),
                }
            )
    return rows


def conflict_rows(name: str, results: dict[str, FamilyFit]) -> list[dict]:
    """One row per minimal conflicting subset (and one row saying so where none was found)."""
    rows = []
    for fam, r in results.items():
        search = r.conflicts
        if search is None:
            continue
        p, noise = r.problem, r.residual_noise
        base = {
            "figure": name,
            "family": fam,
            "numbers": search.numbers,
            "max_size_searched": search.max_size,
        }
        for c in search.conflicts:
            rows.append(
                {
                    **base,
                    "size": len(c.members),
                    "claims": " + ".join(p.observations[i].claim for i in c.members),
                    "worst_residual": _rounded(c.worst, "inf"),
                    "residual_noise": _rounded(noise),
                    "above_noise": int(c.worst - 1.0 > noise) if math.isfinite(noise) else "",
                }
            )
        if not search.conflicts:
            note = "consistent: a set within precision found" if search.witness is not None else "none found"
            rows.append({**base, "size": 0, "claims": note, "worst_residual": ""})
    return rows


def summary_rows(name: str, results: dict[str, FamilyFit]) -> list[dict]:
    rows = []
    for fam, r in results.items():
        p, fit = r.problem, r.fit
        a = r.analysis
        k = int(np.argmax(np.abs(np.nan_to_num(fit.residuals, nan=np.inf))))
        row = {
            "figure": name,
            "family": fam,
            "numbers": len(p.observations),
            "identifiable_dimensions": int(a.dims) if np.isfinite(a.dims) else "",
            "structural_dimensions": int(s) if np.isfinite(s := r.structural_dimensions) else "",
            "phases_visited": " ".join(sorted({ph for run in r.phases for ph in run})),
            "dimensions_note": a.note,
            "profiles_bounded": profiles_bounded(r),
            "free_parameters": len(p.free),
        }
        for i, param in enumerate(p.free):
            row.update(
                _range_columns(
                    param, fit.free_values[i], a.lower[i], a.upper[i], a.ridge[i], open_flag(a, param)
                )
            )
            row[f"stated_{param}"] = float(p.stated_free[i])
        stated = p.combinations(p.stated_free)
        for combo, key in COMBINATION_KEYS.items():
            if len(COMBINATIONS[combo]) == 1 or combo not in a.combo_lower:  # one parameter: its own columns
                continue
            point, lo, hi = a.combo_point[combo], a.combo_lower[combo], a.combo_upper[combo]
            row.update(_range_columns(key, point, lo, hi, a.combo_ridge[combo], open_flag(a, combo)))
            row[f"stated_{key}"] = float(f"{stated[combo]:.4g}")
        search = r.conflicts
        row.update(
            worst_residual=_rounded(fit.worst, "inf"),
            worst_claim=p.observations[k].claim,
            chi_square=_rounded(fit.chi2, "inf"),
            verdict="consistent" if fit.consistent else "inconsistent",
            residual_noise=_rounded(r.residual_noise),
            verdict_above_noise=int(abs(fit.worst - 1.0) > r.residual_noise)
            if math.isfinite(r.residual_noise) and math.isfinite(fit.worst)
            else "",
            fit_source=r.fit_source,
            minimal_conflicts=len(search.conflicts) if search is not None else "",
        )
        rows.append(row)
    return rows


def _rounded(x: float, missing=""):
    """x to 3 decimals as a table shows it; ``missing`` where it is not finite."""
    return round(x, 3) if math.isfinite(x) else missing


def profiles_bounded(r: FamilyFit) -> str:
    """'k of n': of the n quantities profiled (those the structure fixes), how many the data bound, i.e. are
    reported as identifiable (profile above the threshold on both sides, at most a decade wide); '' where
    nothing was profiled. The structural count says what the equations allow, this what the numbers give."""
    pid, free, a = r.profile, tuple(r.problem.free), r.analysis
    if pid is None or not pid.profiles:
        return ""
    bounded = sum(
        not (a.ridge[free.index(n)] if n in free else a.combo_ridge.get(n, True)) for n in pid.profiles
    )
    return f"{bounded} of {len(pid.profiles)}"


def _range_columns(key: str, value, lower, upper, ridge: bool, open_code: int) -> dict:
    """Summary columns of one parameter or combination: best_ (empty where it is a range, never a point),
    lower_/upper_ (a range, or the confidence interval of an identifiable one), identifiable_ (1/0) and
    open_ (the side(s) where the range reaches the bounds within the threshold: unbounded by the data)."""
    return {
        f"best_{key}": "" if ridge else float(f"{value:.4g}"),
        f"lower_{key}": float(f"{lower:.4g}") if np.isfinite(lower) else "",  # "": no interval measured
        f"upper_{key}": float(f"{upper:.4g}") if np.isfinite(upper) else "",
        f"identifiable_{key}": int(not ridge),
        f"open_{key}": ("", "below", "above", "both")[open_code],  # open_flag's code,
    }


def misprint_tables(inverse: Inverse, joint: dict[str, FamilyFit]) -> tuple[list, list]:
    """(hypothesis rows, ranking rows) on the joint problem of each family."""
    hyp_rows, rank_rows = [], []
    points = inverse.mode_settings.scan_points
    for fam, r in joint.items():
        p = r.problem
        rows = [stated_score(p)] + named_hypotheses(p, inverse.hypotheses, points)
        rows += single_changes(p, points)
        hyp_rows += [s.row(fam) for s in rows]
        sd = r.region.sd_log10 if r.region is not None else laplace_sd(p, r.fit.jacobian)
        rank_rows += [{"family": fam, **row} for row in ranking(p, r.fit.free_values, sd)]
    return hyp_rows, rank_rows


def _as_free(problem: Problem, values: dict) -> np.ndarray:
    """A fitted set of another problem as this problem's free vector (stated where it was not free)."""
    return np.array([values.get(p, problem.stated[p]) for p in problem.free], dtype=float)


def run_study(job: InverseJob, claims: dict, figures=None, families=None) -> dict:
    """Everything the study writes, as datasets and rows (no files)."""
    inv = job.inverse
    settings = inv.mode_settings
    figures = list(figures or inv.figures)
    families = list(families or inv.families)
    out = {"datasets": {}, "summary": [], "numbers": [], "conflicts": [], "inverse": inv, "cpu": {}}
    fitted = {fam: [] for fam in families}  # per-figure fits: the joint fit's candidate starts
    for name in figures + ["joint"]:
        joint = name == "joint"
        steps = settings.joint_steps if joint else settings.steps
        results = {}
        for fam in families:
            problem = build_problem(job, claims, name, fam)
            candidates = [_as_free(problem, c) for c in fitted[fam]] if joint else ()
            results[fam] = fit_problem(
                problem, settings, steps, loo=joint, candidates=candidates, conflicts=not joint
            )
            fitted[fam].append(dict(zip(problem.free, results[fam].fit.free_values)))
        out["datasets"][name] = figure_dataset(name, results, inv)
        out["summary"] += summary_rows(name, results)
        out["numbers"] += number_rows(name, results)
        out["conflicts"] += conflict_rows(name, results)
        out["cpu"][name] = sum(r.cpu for r in results.values())
        if joint:
            t0 = time.process_time()
            out["hypotheses"], out["ranking"] = misprint_tables(inv, results)
            out["cpu"]["misprint scans"] = time.process_time() - t0
    return out
