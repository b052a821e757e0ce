"""The whole inverse study: per figure and family a best fit and a sampled region, the joint fit with its
leave-one-out residuals, the misprint scores; results as xarray datasets and table rows.

Every dataset is labelled a FIT: it sits beside the claims table (the forward replication with the stated
parameters) and changes none of its pins.
"""

from __future__ import annotations

import json
import math
import time

import numpy as np
import xarray as xr

from .fit import best_fit, laplace_sd, loo_linear, loo_refit, sample_region
from .forward import Forward
from .hypotheses import named_hypotheses, ranking, single_changes, stated_score
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


def fit_problem(problem: Problem, settings: dict, steps: int, loo: bool = False, candidates=()) -> dict:
    """Best fit, region and (optionally) leave-one-out residuals of one problem."""
    t0 = time.process_time()
    forward = Forward(problem)
    seed = int(settings["seed"])
    fit = best_fit(forward, settings["starts"], settings["max_nfev"], seed, candidates=candidates)
    sampled = steps > 0 and np.isfinite(fit.chi2)  # an infeasible best fit has no region to sample from
    region = sample_region(forward, fit, settings["walkers"], steps, seed) if sampled else None
    # leave-one-out: the joint problem as configured, a single figure always linearised (cheap)
    refit = loo and settings["loo"] == "refit"
    if refit:
        loo_r = loo_refit(forward, fit, settings.get("loo_nfev", settings["max_nfev"]), seed)
    else:
        loo_r = loo_linear(problem, fit) if np.all(np.isfinite(fit.jacobian)) else None
    stated_r = forward.residuals(problem.stated_free)
    return {
        "problem": problem,
        "fit": fit,
        "region": region,
        "loo": loo_r,
        "stated_residuals": stated_r,
        "forward": forward,
        "cpu": time.process_time() - t0,
    }


def _pad(values: np.ndarray, free: tuple, fill=np.nan) -> np.ndarray:
    out = np.full(len(PARAMS), fill, dtype=float)
    for i, p in enumerate(free):
        out[PARAMS.index(p)] = values[i]
    return out


def figure_dataset(name: str, results: dict[str, dict], settings: dict) -> xr.Dataset:
    """One figure (or the joint problem), both families along ``family``."""
    families = list(results)
    first = results[families[0]]["problem"]
    claims = [o.claim for o in first.observations]
    n_samples = max(
        (len(r["region"].samples_free) if r["region"] is not None else 0) for r in results.values()
    )
    n_samples = max(n_samples, 1)
    walkers = int(settings["walkers"])
    shape_fp = (len(families), len(PARAMS))
    v = {k: np.full(shape_fp, np.nan) for k in ("best", "stated", "sd", "laplace", "lo", "hi")}
    combos = list(COMBINATIONS)
    best_c, stated_c = (
        np.full((len(families), len(combos)), np.nan),
        np.full((len(families), len(combos)), np.nan),
    )
    samples = np.full((len(families), n_samples, len(PARAMS)), np.nan)
    loglik = np.full((len(families), n_samples), np.nan)
    acc = np.full((len(families), walkers), np.nan)
    tau = np.full((len(families), len(PARAMS)), np.nan)
    measured, resid, resid_stated, loo = (np.full((len(families), len(claims)), np.nan) for _ in range(4))
    scalars = {
        k: np.full(len(families), np.nan)
        for k in (
            "worst",
            "chi2",
            "consistent",
            "dims",
            "infeasible",
            "evaluations",
            "cpu",
            "converged",
            "steps",
        )
    }
    for f, fam in enumerate(families):
        r = results[fam]
        p, fit, region = r["problem"], r["fit"], r["region"]
        v["best"][f] = _pad(fit.free_values, p.free)
        v["stated"][f] = _pad(p.stated_free, p.free)
        v["lo"][f] = _pad(np.array([p.bounds[k][0] for k in p.free]), p.free)
        v["hi"][f] = _pad(np.array([p.bounds[k][1] for k in p.free]), p.free)
        for c, name_c in enumerate(combos):
            bc, sc = p.combinations(fit.free_values), p.combinations(p.stated_free)
            best_c[f, c], stated_c[f, c] = bc.get(name_c, np.nan), sc.get(name_c, np.nan)
        resid[f] = fit.residuals
        measured[f] = np.array([o.value for o in p.observations]) + fit.residuals * np.array(
            [o.sd for o in p.observations]
        )
        resid_stated[f] = r["stated_residuals"]
        if r["loo"] is not None:
            loo[f] = r["loo"]
        scalars["worst"][f] = fit.worst
        scalars["chi2"][f] = fit.chi2
        scalars["consistent"][f] = float(fit.consistent)
        scalars["dims"][f] = p.identifiable_basis().shape[1]
        scalars["evaluations"][f] = r["forward"].evaluations
        scalars["cpu"][f] = r["cpu"]
        if np.all(np.isfinite(fit.jacobian)):
            v["laplace"][f] = v["sd"][f] = _pad(laplace_sd(p, fit.jacobian), p.free)
        if region is not None:
            n = len(region.samples_free)
            for i in range(n):
                samples[f, i] = _pad(region.samples_free[i], p.free)
            loglik[f, :n] = region.log_likelihood
            acc[f, : len(region.acceptance)] = region.acceptance
            tau[f, : len(region.autocorr_time)] = region.autocorr_time
            v["sd"][f] = _pad(region.sd_log10, p.free)
            v["laplace"][f] = _pad(region.laplace_sd_log10, p.free)
            scalars["infeasible"][f] = region.infeasible_fraction
            scalars["converged"][f] = float(region.converged)
            scalars["steps"][f] = region.steps
    fam_p = ("family", "parameter")
    fc = ("family", "claim")
    ds = xr.Dataset(
        {
            "best_fit": (
                fam_p,
                v["best"],
                {
                    "long_name": "best-fitting parameter set closest to the stated one",
                    "comment": "FIT: reproduces the figure's reported numbers best",
                },
            ),
            "stated": (fam_p, v["stated"], {"long_name": "parameter as stated in the paper"}),
            "lower_bound": (fam_p, v["lo"], {"long_name": "lower physical bound (config inverse.bounds)"}),
            "upper_bound": (fam_p, v["hi"], {"long_name": "upper physical bound (config inverse.bounds)"}),
            "posterior_sd_log10": (
                fam_p,
                v["sd"],
                {
                    "units": "1",
                    "long_name": "posterior spread of log10 parameter",
                    "comment": "sampled if the chain is >= 50 autocorrelation "
                    "times long, else the Laplace (Gauss-Newton) spread",
                },
            ),
            "laplace_sd_log10": (
                fam_p,
                v["laplace"],
                {"units": "1", "long_name": "Laplace spread of log10 parameter"},
            ),
            "best_fit_combination": (
                ("family", "combination"),
                best_c,
                {"long_name": "identifiable combination at the best fit"},
            ),
            "stated_combination": (
                ("family", "combination"),
                stated_c,
                {"long_name": "identifiable combination as stated"},
            ),
            "samples": (
                ("family", "sample", "parameter"),
                samples,
                {
                    "long_name": "posterior samples (emcee, after burn-in)",
                    "comment": "each sample is the set closest to the stated one with its motion",
                },
            ),
            "sample_log_likelihood": (
                ("family", "sample"),
                loglik,
                {"units": "1", "long_name": "log-likelihood of each sample"},
            ),
            "acceptance_fraction": (
                ("family", "walker"),
                acc,
                {"units": "1", "long_name": "emcee acceptance fraction per walker"},
            ),
            "autocorr_time": (
                ("family", "coordinate"),
                tau,
                {
                    "units": "1",
                    "long_name": "integrated autocorrelation time [steps] per identifiable coordinate",
                },
            ),
            "reported": (
                "claim",
                np.array([o.value for o in first.observations]),
                {"long_name": "reported number (claims table)"},
            ),
            "reading_precision": (
                "claim",
                np.array([o.sd for o in first.observations]),
                {"long_name": "reading precision (claim tolerance), one standard deviation"},
            ),
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
            "measured_best": (fc, measured, {"long_name": "number measured at the best fit"}),
            "residual": (
                fc,
                resid,
                {"units": "1", "long_name": "(measured - reported) / reading precision at the best fit"},
            ),
            "residual_stated": (
                fc,
                resid_stated,
                {
                    "units": "1",
                    "long_name": "(measured - reported) / reading precision with the stated parameters",
                },
            ),
            "loo_residual": (
                fc,
                loo,
                {
                    "units": "1",
                    "long_name": "leave-one-out residual (number left out of the fit)",
                    "comment": "method: "
                    + (settings["loo"] if name == "joint" else "linear")
                    + " (linear: r_i / (1 - h_ii) at the best fit; refit: the problem refitted without it)",
                },
            ),
            "worst_residual": (
                "family",
                scalars["worst"],
                {"units": "1", "long_name": "largest |residual| at the best fit"},
            ),
            "chi_square": (
                "family",
                scalars["chi2"],
                {"units": "1", "long_name": "sum of squared residuals at the best fit"},
            ),
            "consistent": (
                "family",
                scalars["consistent"].astype(np.int8),
                {
                    "units": "1",
                    "long_name": "verdict",
                    "flag_values": np.array([0, 1], dtype=np.int8),
                    "flag_meanings": "inconsistent consistent",
                },
            ),
            "identifiable_dimensions": (
                "family",
                scalars["dims"],
                {"units": "1", "long_name": "number of identifiable parameter directions"},
            ),
            "infeasible_fraction": (
                "family",
                scalars["infeasible"],
                {"units": "1", "long_name": "fraction of sampler proposals that were infeasible"},
            ),
            "forward_evaluations": (
                "family",
                scalars["evaluations"],
                {"units": "1", "long_name": "forward-model evaluations"},
            ),
            "chain_converged": (
                "family",
                scalars["converged"],
                {"units": "1", "long_name": "chain >= 50 autocorrelation times (1) or not (0)"},
            ),
            "chain_steps": (
                "family",
                scalars["steps"],
                {"units": "1", "long_name": "emcee steps per walker"},
            ),
            "cpu_time": (
                "family",
                scalars["cpu"],
                {"units": "s", "long_name": "process CPU time of the fit"},
            ),
        },
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
            "combination": (
                "combination",
                np.array(combos, dtype=object),
                {"long_name": "identifiable combination"},
            ),
            "combination_units": (
                "combination",
                np.array([COMBINATION_UNITS[c] for c in combos], dtype=object),
                {"long_name": "units of the combination"},
            ),
            "claim": ("claim", np.array(claims, dtype=object), {"long_name": "claim id (config/claims)"}),
        },
    )
    ds.attrs.update(
        title=f"FIT (inverse study): {first.title}",
        interpretation=INTERPRETATION,
        figure=name,
        settings=json.dumps(settings, sort_keys=True),
        runs=json.dumps([{"name": r.name, "overrides": r.overrides} for r in first.runs], default=str),
    )
    return ds


def summary_rows(name: str, results: dict[str, dict]) -> list[dict]:
    rows = []
    for fam, r in results.items():
        p, fit = r["problem"], r["fit"]
        k = int(np.argmax(np.abs(np.nan_to_num(fit.residuals, nan=np.inf))))
        row = {
            "figure": name,
            "family": fam,
            "numbers": len(p.observations),
            "identifiable_dimensions": p.identifiable_basis().shape[1],
        }
        for i, param in enumerate(p.free):
            row[f"best_{param}"] = float(f"{fit.free_values[i]:.4g}")
            row[f"stated_{param}"] = float(p.stated_free[i])
        row.update(
            worst_residual=round(fit.worst, 3) if math.isfinite(fit.worst) else "inf",
            worst_claim=p.observations[k].claim,
            chi_square=round(fit.chi2, 3) if math.isfinite(fit.chi2) else "inf",
            verdict="consistent" if fit.consistent else "inconsistent",
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
    out = {"datasets": {}, "summary": [], "settings": settings, "cpu": {}}
    fitted = {fam: [] for fam in families}  # per-figure fits: the joint fit's candidate starts
    for name in figures + ["joint"]:
        steps = settings["joint_steps"] if name == "joint" else settings["steps"]
        results = {}
        for fam in families:
            problem = build_problem(config, claims, name, fam)
            candidates = [_as_free(problem, c) for c in fitted[fam]] if name == "joint" else ()
            results[fam] = fit_problem(problem, settings, steps, loo=name == "joint", candidates=candidates)
            fitted[fam].append(dict(zip(problem.free, results[fam]["fit"].free_values)))
        out["datasets"][name] = figure_dataset(name, results, settings)
        out["summary"] += summary_rows(name, results)
        out["cpu"][name] = sum(r["cpu"] for r in results.values())
        if name == "joint":
            t0 = time.process_time()
            out["hypotheses"], out["ranking"] = misprint_tables(config, claims, results, settings)
            out["cpu"]["misprint scans"] = time.process_time() - t0
    return out
