"""The whole inverse study: per figure and family a best fit and a sampled region, the joint fit with its
leave-one-out residuals, the misprint scores; results as xarray datasets and table rows.

Every dataset is labelled a FIT: it sits beside the claims table (the forward replication with the stated
parameters) and changes none of its pins.
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass

import numpy as np
import xarray as xr

from .conflicts import CONFLICT_NFEV, minimal_conflicts
from .fit import best_fit, fit_at, laplace_sd, loo_linear, loo_refit, sample_region
from .forward import Forward
from .hypotheses import named_hypotheses, ranking, single_changes, stated_score
from .identify import (
    PROFILE_THRESHOLD,
    combination_rows,
    flat_extent,
    identify,
    on_ridge,
    parameter_ranges,
)
from .problem import COMBINATION_UNITS, COMBINATIONS, PARAMS, SYMBOLS, UNITS, Problem, build_problem

INTERPRETATION = (
    "FIT, not a replication: parameter sets of the model family under which the paper's reported numbers "
    "(claims table values; noise = each claim's reading precision) are reproduced jointly by the exact "
    "event-driven solver. The claims table (stated parameters) is unchanged by this study."
)


def settings_of(config: dict) -> dict:
    """The settings of the configured mode (``inverse.long``), checked by the typed config layer."""
    inv = config["inverse"]
    mode = "long" if inv.get("long", False) else "default"
    return {**inv["settings"][mode], "mode": mode}


def fit_problem(
    problem: Problem, settings: dict, steps: int, loo: bool = False, candidates=(), conflicts: bool = True
) -> dict:
    """Best fit, region, minimal conflicting subsets (if inconsistent and ``conflicts``), identifiable
    dimensions and (optionally) leave-one-out residuals of one problem.

    A conflict search that finds a set putting every number within precision overturns the least-squares
    verdict: the fit is then that set (``fit_source`` "conflict search"), and the figure is consistent.
    """
    t0 = time.process_time()
    forward = Forward(problem)
    seed = int(settings["seed"])
    fit = best_fit(forward, settings["starts"], settings["max_nfev"], seed, candidates=candidates)
    sampled = steps > 0 and np.isfinite(fit.chi2)  # an infeasible best fit has no region to sample from
    region = sample_region(forward, fit, settings["walkers"], steps, seed) if sampled else None
    search, source = None, "least squares"
    if conflicts and not fit.consistent:
        seeds = [fit.free_values, problem.stated_free] + (list(region.samples_free) if region else [])
        # a subset fit gets at most twice a full fit's iterations: the default build's CONFLICT_NFEV, fewer in
        # a build whose fits are token ones (CI size)
        nfev = min(CONFLICT_NFEV, 2 * int(settings["max_nfev"]))
        search = minimal_conflicts(forward, seeds, max_nfev=nfev)
        if search.witness is not None:
            closest = problem.closest_equivalent(search.witness)
            fit = fit_at(forward, closest if problem.in_bounds(closest) else search.witness)
            source = "conflict search"
    ident = identify(forward, fit.free_values, jacobian=fit.jacobian) if np.isfinite(fit.chi2) else None
    # leave-one-out: the joint problem as configured, a single figure always linearised (cheap)
    refit = loo and settings["loo"] == "refit"
    if refit:
        loo_r = loo_refit(forward, fit, settings.get("loo_nfev", settings["max_nfev"]), seed)
    else:
        loo_r = loo_linear(problem, fit) if np.all(np.isfinite(fit.jacobian)) else None
    stated_r = forward.residuals(problem.stated_free)
    noise = residual_noise(problem, fit.free_values) if np.isfinite(fit.chi2) else np.nan
    return {
        "problem": problem,
        "fit": fit,
        "region": region,
        "loo": loo_r,
        "stated_residuals": stated_r,
        "residual_noise": noise,
        "conflicts": search,
        "identification": ident,
        "fit_source": source,
        "forward": forward,
        "cpu": time.process_time() - t0,
    }


def residual_noise(problem: Problem, free_values) -> float:
    """Numerical noise of the residuals at a set: the largest change when the sample spacing is halved
    (step halving of the time-series metrics). A verdict or conflict margin below it is not a result."""
    dt = float(problem.run_settings["output_dt"])
    coarse = Forward(problem).residuals(free_values)
    fine = Forward(problem, {"output_dt": dt / 2}).residuals(free_values)
    d = np.abs(fine - coarse)
    return float(np.max(d[np.isfinite(d)])) if np.any(np.isfinite(d)) else np.nan


def _pad(values: np.ndarray, free: tuple, fill=np.nan) -> np.ndarray:
    out = np.full(len(PARAMS), fill, dtype=float)
    for i, p in enumerate(free):
        out[PARAMS.index(p)] = values[i]
    return out


COMBINATION_KEYS = {
    "K/M": "K_over_M",
    "C/M": "C_over_M",
    "mu_s N/M": "mu_s_N_over_M",
    "sigma": "sigma",
    "v_p": "v_p",
}

IDENTIFIABILITY_METHOD = (
    "chi-square profiles at the best fit along every direction of the free log10 parameters: the structural "
    "null space (sets with the same motion) and the right-singular vectors of the residual Jacobian in the "
    f"identifiable coordinates; a direction is a ridge when chi-square stays within delta chi2 = "
    f"{PROFILE_THRESHOLD:g} (one reading precision) of its minimum up to the parameter bounds on both sides, "
    "or when the figure has fewer numbers than identifiable coordinates (no first-order constraint); "
    "identifiable dimensions = free parameters - ridges (stickslip.inverse.identify)"
)
CONFLICT_METHOD = (
    "subsets of the figure's reported numbers by increasing size up to conflict_search_max_size; a subset "
    "conflicts when the best fit to it alone (least squares, "
    f"at most {CONFLICT_NFEV} iterations, from the best witness) leaves a residual above 1; minimal: no "
    "conflicting proper subset (stickslip.inverse.conflicts)"
)


@dataclass
class _Analysis:
    """The per-family numbers of one problem the datasets and tables are made of."""

    fit_point: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    ridge: np.ndarray
    combo_point: dict
    combo_lower: dict
    combo_upper: dict
    dims: float


def analyse(r: dict) -> _Analysis:
    """Ranges along the flat set for the parameters and combinations of one fitted problem (computed once,
    kept in ``r``)."""
    if "analysis" not in r:
        r["analysis"] = _analyse(r)
    return r["analysis"]


def _analyse(r: dict) -> _Analysis:
    p, fit, ident = r["problem"], r["fit"], r["identification"]
    v = np.asarray(fit.free_values, dtype=float)
    combos = p.combinations(v)
    if ident is None:
        nan = np.full(len(p.free), np.nan)
        return _Analysis(v, nan, nan, np.zeros(len(p.free), bool), combos, {}, {}, np.nan)
    lower, upper = parameter_ranges(p, v, ident)
    rows = combination_rows(p)
    ext = flat_extent(p, v, ident, np.array(list(rows.values()))) if rows else np.zeros((0, 2))
    c_lo = {n: combos[n] * 10.0 ** e[0] for n, e in zip(rows, ext) if n in combos}
    c_hi = {n: combos[n] * 10.0 ** e[1] for n, e in zip(rows, ext) if n in combos}
    return _Analysis(v, lower, upper, on_ridge(lower, upper), combos, c_lo, c_hi, float(ident.dimensions))


def figure_dataset(name: str, results: dict[str, dict], settings: dict) -> xr.Dataset:
    """One figure (or the joint problem), both families along ``family``; every variable has units."""
    families = list(results)
    first = results[families[0]]["problem"]
    claims = [o.claim for o in first.observations]
    nf, npar = len(families), len(PARAMS)
    analyses = {fam: analyse(results[fam]) for fam in families}
    n_samples = max(
        [len(r["region"].samples_free) for r in results.values() if r["region"] is not None] + [1]
    )
    walkers = int(settings["walkers"])
    fam_d, fp, fc = ("family",), ("family", "parameter"), ("family", "claim")
    data = {}

    def put(key, dims, values, units, long_name, **attrs):
        data[key] = (dims, values, {"units": units, "long_name": long_name, **attrs})

    # per parameter (each its own variable: one unit per variable)
    kinds = {
        "best_fit": "best-fitting value where the numbers pin it (NaN along a ridge: see flat_lower/upper)",
        "fit_point": "one member of the best-fitting set (the one closest to the stated set); not an "
        "estimate where the parameter lies on a ridge",
        "flat_lower": "lowest value over the flat set (chi-square within the threshold) in the bounds",
        "flat_upper": "highest value over the flat set (chi-square within the threshold) in the bounds",
        "stated": "value as stated in the paper",
        "lower_bound": "lower physical bound (config inverse.bounds)",
        "upper_bound": "upper physical bound (config inverse.bounds)",
    }
    arrays = {k: np.full((nf, npar), np.nan) for k in kinds}
    ridge = np.zeros((nf, npar), dtype=np.int8)
    sd, laplace = np.full((nf, npar), np.nan), np.full((nf, npar), np.nan)
    samples = np.full((nf, n_samples, npar), np.nan)
    for f, fam in enumerate(families):
        r, a = results[fam], analyses[fam]
        p = r["problem"]
        arrays["fit_point"][f] = _pad(a.fit_point, p.free)
        arrays["best_fit"][f] = _pad(np.where(a.ridge, np.nan, a.fit_point), p.free)
        arrays["flat_lower"][f] = _pad(a.lower, p.free)
        arrays["flat_upper"][f] = _pad(a.upper, p.free)
        arrays["stated"][f] = _pad(p.stated_free, p.free)
        arrays["lower_bound"][f] = _pad(np.array([p.bounds[k][0] for k in p.free]), p.free)
        arrays["upper_bound"][f] = _pad(np.array([p.bounds[k][1] for k in p.free]), p.free)
        ridge[f] = _pad(a.ridge.astype(float), p.free, fill=0).astype(np.int8)
        if np.all(np.isfinite(r["fit"].jacobian)):
            laplace[f] = sd[f] = _pad(laplace_sd(p, r["fit"].jacobian), p.free)
        if r["region"] is not None:
            for i, s in enumerate(r["region"].samples_free):
                samples[f, i] = _pad(s, p.free)
            sd[f] = _pad(r["region"].sd_log10, p.free)
            laplace[f] = _pad(r["region"].laplace_sd_log10, p.free)
    for kind, long_name in kinds.items():
        for j, param in enumerate(PARAMS):
            put(f"{kind}_{param}", fam_d, arrays[kind][:, j], UNITS[param], f"{SYMBOLS[param]}: {long_name}")
    for j, param in enumerate(PARAMS):
        put(
            f"samples_{param}",
            ("family", "sample"),
            samples[:, :, j],
            UNITS[param],
            f"{SYMBOLS[param]}: posterior samples (emcee, after burn-in)",
            comment="each sample is the set closest to the stated one with its motion",
        )
    put(
        "on_ridge",
        fp,
        ridge,
        "1",
        "parameter moves along a flat direction (1): reported as flat_lower..flat_upper, never a point",
        flag_values=np.array([0, 1], dtype=np.int8),
        flag_meanings="pinned on_ridge",
    )
    put(
        "posterior_sd_log10",
        fp,
        sd,
        "1",
        "posterior spread of log10 parameter",
        comment="sampled if the chain is >= 50 autocorrelation times long, else the Laplace (Gauss-Newton) "
        "spread; in the identifiable directions only (a ridge's extent is flat_lower..flat_upper)",
    )
    put("laplace_sd_log10", fp, laplace, "1", "Laplace spread of log10 parameter")

    # identifiable combinations, each with its own unit
    combos = list(COMBINATIONS)
    for c in combos:
        key = COMBINATION_KEYS[c]
        point, lo, hi, stated = (np.full(nf, np.nan) for _ in range(4))
        for f, fam in enumerate(families):
            a, p = analyses[fam], results[fam]["problem"]
            if c in a.combo_point:
                lo[f], hi[f] = a.combo_lower.get(c, np.nan), a.combo_upper.get(c, np.nan)
                moves = bool(on_ridge(lo[f], hi[f])) or not np.isfinite(lo[f])
                point[f] = np.nan if moves else a.combo_point[c]
                stated[f] = p.combinations(p.stated_free).get(c, np.nan)
        units = COMBINATION_UNITS[c]
        put(f"best_fit_{key}", fam_d, point, units, f"{c} at the best fit (NaN where it moves along a ridge)")
        put(f"flat_lower_{key}", fam_d, lo, units, f"{c}: lowest over the flat set")
        put(f"flat_upper_{key}", fam_d, hi, units, f"{c}: highest over the flat set")
        put(f"stated_{key}", fam_d, stated, units, f"{c} as stated")

    # profiles along every direction
    nd = npar
    vec = np.full((nf, nd, npar), np.nan)
    dir_vals = {
        k: np.full((nf, nd), np.nan) for k in ("s", "kind", "tlo", "thi", "blo", "bhi", "rise", "ridge")
    }
    for f, fam in enumerate(families):
        ident, p = results[fam]["identification"], results[fam]["problem"]
        if ident is None:
            continue
        for i, pr in enumerate(ident.profiles):
            vec[f, i] = _pad(pr.direction, p.free, fill=0.0)
            kind = 0 if pr.structural else (1 if pr.unconstrained else 2)
            row = (
                pr.singular_value,
                kind,
                pr.t_lower,
                pr.t_upper,
                pr.bound_lower,
                pr.bound_upper,
                pr.rise,
                pr.ridge,
            )
            for k, value in zip(dir_vals, row):
                dir_vals[k][f, i] = float(value)
    fd = ("family", "direction")
    put(
        "direction_vector",
        ("family", "direction", "parameter"),
        vec,
        "1",
        "unit direction in log10 of the free parameters",
    )
    put(
        "direction_singular_value",
        fd,
        dir_vals["s"],
        "1",
        "singular value of the residual Jacobian (per log10 unit); 0: structural or unconstrained",
    )
    put(
        "direction_kind",
        fd,
        dir_vals["kind"],
        "1",
        "how the direction was found",
        flag_values=np.array([0.0, 1.0, 2.0]),
        flag_meanings="structural unconstrained profiled",
        comment="structural: exactly the same motion; unconstrained: beyond the number of reported numbers; "
        "profiled: a singular direction of the Jacobian",
    )
    put(
        "profile_t_lower",
        fd,
        dir_vals["tlo"],
        "1",
        "lower end [log10 units] of the interval within the threshold",
    )
    put(
        "profile_t_upper",
        fd,
        dir_vals["thi"],
        "1",
        "upper end [log10 units] of the interval within the threshold",
    )
    put(
        "profile_reaches_lower_bound",
        fd,
        dir_vals["blo"],
        "1",
        "within the threshold down to the parameter bounds (1) or not (0)",
    )
    put(
        "profile_reaches_upper_bound",
        fd,
        dir_vals["bhi"],
        "1",
        "within the threshold up to the parameter bounds (1) or not (0)",
    )
    put(
        "profile_rise",
        fd,
        dir_vals["rise"],
        "1",
        "largest chi-square rise above the profile's minimum within the interval",
    )
    put("direction_is_ridge", fd, dir_vals["ridge"], "1", "ridge (1): not identifiable")

    # per claim (dimensionless; the reported numbers with their units are in numbers.csv)
    resid, resid_stated, loo = (np.full((nf, len(claims)), np.nan) for _ in range(3))
    for f, fam in enumerate(families):
        r = results[fam]
        resid[f] = r["fit"].residuals
        resid_stated[f] = r["stated_residuals"]
        if r["loo"] is not None:
            loo[f] = r["loo"]
    put("residual", fc, resid, "1", "(measured - reported) / reading precision at the best fit")
    put(
        "residual_stated",
        fc,
        resid_stated,
        "1",
        "(measured - reported) / reading precision with the stated parameters",
    )
    put(
        "loo_residual",
        fc,
        loo,
        "1",
        "leave-one-out residual (number left out of the fit)",
        comment="method: "
        + (settings["loo"] if name == "joint" else "linear")
        + " (linear: r_i / (1 - h_ii) at the best fit; refit: the problem refitted without it)",
    )

    # minimal conflicting subsets
    n_conf = max([len(r["conflicts"].conflicts) for r in results.values() if r["conflicts"]] + [1])
    member = np.zeros((nf, n_conf, len(claims)), dtype=np.int8)
    size, worst_c = np.zeros((nf, n_conf)), np.full((nf, n_conf), np.nan)
    searched = {k: np.full(nf, np.nan) for k in ("max_size", "fitted", "count")}
    for f, fam in enumerate(families):
        search = results[fam]["conflicts"]
        if search is None:
            continue
        searched["max_size"][f], searched["fitted"][f] = search.max_size, search.subsets_fitted
        searched["count"][f] = len(search.conflicts)
        for i, c in enumerate(search.conflicts):
            member[f, i, list(c.members)] = 1
            size[f, i], worst_c[f, i] = len(c.members), c.worst
    put(
        "conflict_member",
        ("family", "conflict", "claim"),
        member,
        "1",
        "claim belongs to the minimal conflicting subset (1)",
        comment=CONFLICT_METHOD,
    )
    put(
        "conflict_size",
        ("family", "conflict"),
        size,
        "1",
        "numbers in the minimal conflicting subset (0: no subset)",
    )
    put(
        "conflict_worst_residual",
        ("family", "conflict"),
        worst_c,
        "1",
        "smallest worst |residual| any fit to the subset alone reached (> 1)",
    )
    put(
        "conflict_search_max_size",
        fam_d,
        searched["max_size"],
        "1",
        "largest subset size searched (NaN: not searched, the fit is consistent)",
    )
    put(
        "conflict_subsets_fitted",
        fam_d,
        searched["fitted"],
        "1",
        "subsets fitted alone (the others had a witness or held a conflict)",
    )
    put("conflict_count", fam_d, searched["count"], "1", "minimal conflicting subsets found")

    # per family
    def scalar(fn):
        return np.array([fn(results[fam], analyses[fam]) for fam in families], dtype=float)

    put(
        "worst_residual",
        fam_d,
        scalar(lambda r, a: r["fit"].worst),
        "1",
        "largest |residual| at the best fit",
    )
    put(
        "chi_square",
        fam_d,
        scalar(lambda r, a: r["fit"].chi2),
        "1",
        "sum of squared residuals at the best fit",
    )
    put(
        "consistent",
        fam_d,
        scalar(lambda r, a: r["fit"].consistent).astype(np.int8),
        "1",
        "verdict",
        flag_values=np.array([0, 1], dtype=np.int8),
        flag_meanings="inconsistent consistent",
    )
    put(
        "fit_source",
        fam_d,
        scalar(lambda r, a: r["fit_source"] == "conflict search").astype(np.int8),
        "1",
        "where the best fit comes from",
        flag_values=np.array([0, 1], dtype=np.int8),
        flag_meanings="least_squares conflict_search_witness",
    )
    put(
        "identifiable_dimensions",
        fam_d,
        scalar(lambda r, a: a.dims),
        "1",
        "identifiable parameter directions",
        comment=IDENTIFIABILITY_METHOD,
        threshold_delta_chi2=PROFILE_THRESHOLD,
    )
    put(
        "ridge_directions",
        fam_d,
        scalar(lambda r, a: len(r["problem"].free) - a.dims),
        "1",
        "flat directions (ridges) of the free parameters",
    )
    put(
        "motion_dimensions",
        fam_d,
        scalar(lambda r, a: r["problem"].identifiable_basis().shape[1]),
        "1",
        "directions that change the motion at all (rank of the combination map)",
    )
    put(
        "free_parameters",
        fam_d,
        scalar(lambda r, a: len(r["problem"].free)),
        "1",
        "free parameters of the fit",
    )
    region = {
        "infeasible": lambda r, a: r["region"].infeasible_fraction if r["region"] else np.nan,
        "converged": lambda r, a: float(r["region"].converged) if r["region"] else np.nan,
        "steps": lambda r, a: r["region"].steps if r["region"] else np.nan,
    }
    put(
        "infeasible_fraction",
        fam_d,
        scalar(region["infeasible"]),
        "1",
        "fraction of sampler proposals that were infeasible",
    )
    put(
        "forward_evaluations",
        fam_d,
        scalar(lambda r, a: r["forward"].evaluations),
        "1",
        "forward-model evaluations",
    )
    put(
        "chain_converged",
        fam_d,
        scalar(region["converged"]),
        "1",
        "chain >= 50 autocorrelation times (1) or not (0)",
    )
    put("chain_steps", fam_d, scalar(region["steps"]), "1", "emcee steps per walker")
    put("cpu_time", fam_d, scalar(lambda r, a: r["cpu"]), "s", "process CPU time of the fit")
    acc = np.full((nf, walkers), np.nan)
    tau = np.full((nf, npar), np.nan)
    loglik = np.full((nf, n_samples), np.nan)
    for f, fam in enumerate(families):
        reg = results[fam]["region"]
        if reg is not None:
            acc[f, : len(reg.acceptance)] = reg.acceptance
            tau[f, : len(reg.autocorr_time)] = reg.autocorr_time
            loglik[f, : len(reg.log_likelihood)] = reg.log_likelihood
    put("acceptance_fraction", ("family", "walker"), acc, "1", "emcee acceptance fraction per walker")
    put(
        "autocorr_time",
        ("family", "coordinate"),
        tau,
        "1",
        "integrated autocorrelation time [steps] per identifiable coordinate",
    )
    put("sample_log_likelihood", ("family", "sample"), loglik, "1", "log-likelihood of each sample")
    ds = xr.Dataset(
        data,
        coords={
            "family": ("family", np.array(families, dtype=object), {"long_name": "model family"}),
            "parameter": (
                "parameter",
                np.array(PARAMS, dtype=object),
                {"long_name": "parameter (BeltParams field)"},
            ),
            "parameter_units": (
                "parameter",
                np.array([UNITS[p] for p in PARAMS], dtype=object),
                {"long_name": "units of the parameter"},
            ),
            "parameter_symbol": (
                "parameter",
                np.array([SYMBOLS[p] for p in PARAMS], dtype=object),
                {"long_name": "symbol of the parameter"},
            ),
            "claim": ("claim", np.array(claims, dtype=object), {"long_name": "claim id (config/claims)"}),
            "claim_unit": (
                "claim",
                np.array([o.unit for o in first.observations], dtype=object),
                {"long_name": "unit of the reported number"},
            ),
            "claim_metric": (
                "claim",
                np.array([o.metric for o in first.observations], dtype=object),
                {"long_name": "measured metric"},
            ),
            "claim_figure": (
                "claim",
                np.array([o.figure for o in first.observations], dtype=object),
                {"long_name": "figure of the reported number"},
            ),
        },
    )
    ds.attrs.update(
        title=f"FIT (inverse study): {first.title}",
        interpretation=INTERPRETATION,
        figure=name,
        settings=json.dumps(settings, sort_keys=True),
        runs=json.dumps([{"name": r.name, "overrides": r.overrides} for r in first.runs], default=str),
        identifiability_method=IDENTIFIABILITY_METHOD,
        conflict_method=CONFLICT_METHOD,
    )
    return ds


def number_rows(name: str, results: dict[str, dict]) -> list[dict]:
    """Each reported number with its unit, precision and the measured value at the best fit, per family."""
    rows = []
    for fam, r in results.items():
        p, fit = r["problem"], r["fit"]
        members = set()
        if r["conflicts"] is not None:
            members = {i for c in r["conflicts"].conflicts for i in c.members}
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
                    "residual_stated": round(float(r["stated_residuals"][i]), 3),
                    "in_a_conflict": int(i in members),
                }
            )
    return rows


def conflict_rows(name: str, results: dict[str, dict]) -> list[dict]:
    """One row per minimal conflicting subset (and one row saying so where none was found)."""
    rows = []
    for fam, r in results.items():
        search = r["conflicts"]
        if search is None:
            continue
        p, noise = r["problem"], r["residual_noise"]
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
                    "worst_residual": round(c.worst, 3) if math.isfinite(c.worst) else "inf",
                    "residual_noise": round(noise, 3) if math.isfinite(noise) else "",
                    "above_noise": int(c.worst - 1.0 > noise) if math.isfinite(noise) else "",
                }
            )
        if not search.conflicts:
            note = "consistent: a set within precision found" if search.witness is not None else "none found"
            rows.append({**base, "size": 0, "claims": note, "worst_residual": ""})
    return rows


def summary_rows(name: str, results: dict[str, dict]) -> list[dict]:
    rows = []
    for fam, r in results.items():
        p, fit = r["problem"], r["fit"]
        a = analyse(r)
        k = int(np.argmax(np.abs(np.nan_to_num(fit.residuals, nan=np.inf))))
        row = {
            "figure": name,
            "family": fam,
            "numbers": len(p.observations),
            "identifiable_dimensions": int(a.dims) if np.isfinite(a.dims) else "",
            "free_parameters": len(p.free),
        }
        for i, param in enumerate(p.free):
            if a.ridge[i]:  # along a ridge: a range, never a point
                row[f"lower_{param}"] = float(f"{a.lower[i]:.4g}")
                row[f"upper_{param}"] = float(f"{a.upper[i]:.4g}")
            else:
                row[f"best_{param}"] = float(f"{fit.free_values[i]:.4g}")
            row[f"stated_{param}"] = float(p.stated_free[i])
        search = r["conflicts"]
        row.update(
            worst_residual=round(fit.worst, 3) if math.isfinite(fit.worst) else "inf",
            worst_claim=p.observations[k].claim,
            chi_square=round(fit.chi2, 3) if math.isfinite(fit.chi2) else "inf",
            verdict="consistent" if fit.consistent else "inconsistent",
            residual_noise=round(r["residual_noise"], 3) if math.isfinite(r["residual_noise"]) else "",
            verdict_above_noise=int(abs(fit.worst - 1.0) > r["residual_noise"])
            if math.isfinite(r["residual_noise"]) and math.isfinite(fit.worst)
            else "",
            fit_source=r["fit_source"],
            minimal_conflicts=len(search.conflicts) if search is not None else "",
        )
        rows.append(row)
    return rows


def misprint_tables(config: dict, claims: dict, joint: dict[str, dict], settings: dict) -> tuple[list, list]:
    """(hypothesis rows, ranking rows) on the joint problem of each family."""
    hyp_rows, rank_rows = [], []
    for fam, r in joint.items():
        p = r["problem"]
        rows = [stated_score(p)] + named_hypotheses(
            p, config["inverse"]["hypotheses"], settings["scan_points"]
        )
        rows += single_changes(p, settings["scan_points"])
        hyp_rows += [s.row(fam) for s in rows]
        sd = r["region"].sd_log10 if r["region"] is not None else laplace_sd(p, r["fit"].jacobian)
        rank_rows += [{"family": fam, **row} for row in ranking(p, r["fit"].free_values, sd)]
    return hyp_rows, rank_rows


def _as_free(problem: Problem, values: dict) -> np.ndarray:
    """A fitted set of another problem as this problem's free vector (stated where it was not free)."""
    return np.array([values.get(p, problem.stated[p]) for p in problem.free], dtype=float)


def run_study(config: dict, claims: dict, figures=None, families=None) -> dict:
    """Everything the study writes, as datasets and rows (no files)."""
    settings = settings_of(config)
    inv = config["inverse"]
    figures = list(figures or inv["figures"])
    families = list(families or inv["families"])
    out = {"datasets": {}, "summary": [], "numbers": [], "conflicts": [], "settings": settings, "cpu": {}}
    fitted = {fam: [] for fam in families}  # per-figure fits: the joint fit's candidate starts
    for name in figures + ["joint"]:
        steps = settings["joint_steps"] if name == "joint" else settings["steps"]
        results = {}
        for fam in families:
            problem = build_problem(config, claims, name, fam)
            candidates = [_as_free(problem, c) for c in fitted[fam]] if name == "joint" else ()
            results[fam] = fit_problem(
                problem,
                settings,
                steps,
                loo=name == "joint",
                candidates=candidates,
                conflicts=name != "joint",
            )
            fitted[fam].append(dict(zip(problem.free, results[fam]["fit"].free_values)))
        out["datasets"][name] = figure_dataset(name, results, settings)
        out["summary"] += summary_rows(name, results)
        out["numbers"] += number_rows(name, results)
        out["conflicts"] += conflict_rows(name, results)
        out["cpu"][name] = sum(r["cpu"] for r in results.values())
        if name == "joint":
            t0 = time.process_time()
            out["hypotheses"], out["ranking"] = misprint_tables(config, claims, results, settings)
            out["cpu"]["misprint scans"] = time.process_time() - t0
    return out
