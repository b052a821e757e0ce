# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # What the paper's numbers imply — an inverse study (a FIT, beside the claims table)
#
# The claims table replicates the paper *forward*: it runs the model with the parameters the paper states and
# compares the result with each number the paper reports. Several figures (Fig. 2, Figs. 6–8) are not
# reproduced by any reading. This notebook asks the inverse question: **is there any parameter set of the
# model under which a figure's reported numbers are mutually consistent, and how far is it from the stated
# one?** Nothing here changes a claim: the parameter sets below are fitted, and labelled so.
#
# **Model families** (both can stick; the printed sign of Eq. 3 cannot): *consistent* — friction drives the
# mass toward the belt velocity, μ = μ_s (1 − σ|v_r|); *plateau* — the same, levelling off beyond a relative
# speed v_p (Fig. 17's text: 0.6 mm/s). Free: σ, C, μ_s, N, K, M (and v_p), within physical bounds
# (`config/inverse.yaml`, each with its reason). **Data**: each figure's reported numbers from the claims
# table, each with its reading precision (the claim's tolerance) as one standard deviation. **Forward
# model**: the exact event-driven solver, measured exactly like the claims; a run that fails or cannot produce
# a reported number (e.g. never sticks) is infeasible — likelihood zero, not a zero residual.
#
# **What can be identified at all** is derived from the equations, exactly (`stickslip.inverse.structure`,
# sympy). Divided by M, each phase of the motion a run visits depends on a few combinations: in slip K/M, the
# slip damping (C − μ_s N σ)/M and the slip equilibrium; in stick the release position (μ_s N − C V_b)/K;
# beyond the plateau C/M, its equilibrium and the switching speed v_p. The **structural dimension** is the
# rank of their Jacobian with respect to the log parameters over the phases the best fit visits, in exact
# rational arithmetic, so the same on every CPU (Fig. 2, consistent: K/M, (C − μ_s N σ)/M and x_r, three). The
# identifiable dimensions are that rank, at most the number of reported numbers. A quantity the structure
# leaves free is a **range** over every parameter set with the same motion (the fibre), never a point. What
# the data bound of the rest is measured by the **profile likelihood** (Raue et al. 2009): each quantity the
# structure fixes is fixed on a grid and χ² re-minimised over everything else (threshold Δχ² = 3.84, 95 %
# pointwise); open profiles are ranges too, and no quantity whose interval spans more than a decade is called
# identifiable. Every fit ends at its minimum: a profile point below the fit restarts it. The straight-line χ²
# profiles of earlier builds are kept as a diagnostic.
#
# **Verdict**: *consistent* when the best fit puts every number within its reading precision (|residual| ≤ 1).

# %%
import json

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from IPython.display import Image, Markdown, display

from stickslip import catalogue as paths
from stickslip.io.netcdf import read_dataset

summary = pd.read_csv(paths.inverse_table("summary"))
conflicts = pd.read_csv(paths.inverse_table("conflicts"))
numbers = pd.read_csv(paths.inverse_table("numbers"))
hypotheses = pd.read_csv(paths.inverse_table("hypotheses"))
ranking = pd.read_csv(paths.inverse_table("ranking"))
FIGURES = list(dict.fromkeys(summary["figure"]))
data = {name: read_dataset(paths.inverse_dataset(name)) for name in FIGURES}
settings = json.loads(data["joint"].attrs["settings"])
shown = ", ".join(
    f"{k} = {', '.join(map(str, v)) if isinstance(v, list) else v}"
    for k, v in settings.items()
    if k != "mode"
)
display(Markdown(f"Study run in **{settings['mode']}** mode: {shown}."))

# %% [markdown]
# ## 1. Per figure: are the reported numbers consistent under some parameter set?
#
# One row per figure and family: the identifiable dimensions, the fitted parameters and the combinations
# K/M, C/M, μ_s N/M — a value with its 95 % profile-likelihood interval `[lo–hi]` where the numbers identify
# it, a **range** `lo–hi` (no point) where they do not, marked *open below / above* where the range runs to
# the parameter bounds within the threshold — with the stated value in brackets, the worst residual (in
# reading-precision units) and which claim it belongs to.

# %%
params = ["sigma", "damping", "mu_s", "normal_force", "stiffness", "mass", "plateau_speed"]
symbols = dict(zip(params, ["σ", "C", "μ_s", "N", "K", "M", "v_p"]))
symbols.update(K_over_M="K/M", C_over_M="C/M", mu_s_N_over_M="μ_s N/M")


def pairs(row):
    out = []
    for p in symbols:
        best, stated = row.get(f"best_{p}"), row.get(f"stated_{p}")
        lo, hi, side = row.get(f"lower_{p}"), row.get(f"upper_{p}"), row.get(f"open_{p}")
        if pd.isna(lo):
            continue  # not free in this fit
        if pd.notna(best):
            out.append(f"{symbols[p]} {best:.3g} [{lo:.3g}–{hi:.3g}] ({stated:g})")
        else:
            opens = f", open {side}" if isinstance(side, str) and side else ""
            out.append(f"{symbols[p]} range {lo:.3g}–{hi:.3g}{opens} ({stated:g})")
    return ", ".join(out)


def pairs_html(row):
    """One quantity per line: a range list set in a table cell otherwise wraps to a word per line."""
    return pairs(row).replace(", open", "; open").replace(", ", "<br>").replace("; open", ", open")


# the answer first (verdict, the worst number), so it is in view without scrolling; the ranges after it
table = summary.assign(**{"fitted (stated)": summary.apply(pairs_html, axis=1)})[
    [
        "figure",
        "family",
        "verdict",
        "worst_residual",
        "worst_claim",
        "verdict_above_noise",
        "residual_noise",
        "numbers",
        "free_parameters",
        "identifiable_dimensions",
        "fitted (stated)",
    ]
]
display(
    table.style.apply(
        lambda r: (
            ["background-color: #d8f0d8" if r["verdict"] == "consistent" else "background-color: #f6d8d8"]
            * len(r)
        ),
        axis=1,
    )
    .format(precision=3)
    .set_properties(subset=["fitted (stated)"], **{"min-width": "24em", "text-align": "left"})
    .hide(axis="index")
)

# %% [markdown]
# ### What the numbers identify: straight-line profiles and the profile likelihood
#
# For each fit: the free parameters, the structural dimension derived from the equations, the identifiable
# dimensions (the structural ones, at most the number of reported numbers), the quantities profiled, the
# straight-line ridges by kind as a diagnostic (*structural*: the same motion along a straight line;
# *unconstrained*: beyond the number of reported numbers; *profiled*: a singular direction of the Jacobian
# along which χ² stays within the threshold up to the bounds) and the ranges. The method, as stored in every
# dataset:

# %%
display(Markdown(f"> {data['joint'].identifiable_dimensions.attrs['comment']}"))
KINDS = {0: "structural", 1: "unconstrained", 2: "profiled"}
rows = []
for name in FIGURES:
    ds = data[name]
    for fam in ds.family.values:
        sub = ds.sel(family=fam)
        ridge = sub.direction_is_ridge.values == 1
        kind = sub.direction_kind.values
        flat_ranges = [
            f"{symbols[p]} {float(sub[f'flat_lower_{p}']):.3g}–{float(sub[f'flat_upper_{p}']):.3g}"
            for j, p in enumerate(params)
            if int(sub.on_ridge.isel(parameter=j))
        ]
        rows.append(
            {
                "figure": name,
                "family": str(fam),
                "free": int(sub.free_parameters),
                **{f"{k} ridges": int(np.sum(ridge & (kind == i))) for i, k in KINDS.items()},
                "structural": sub.structural_dimensions.item(),
                "identifiable": sub.identifiable_dimensions.item(),
                "largest rise on a profiled ridge": float(
                    np.nanmax(np.where(ridge & (kind == 2), sub.profile_rise.values, np.nan), initial=np.nan)
                )
                if np.any(ridge & (kind == 2))
                else np.nan,
                "profiled": ", ".join(
                    str(q)
                    for q, c in zip(ds.quantity.values, sub.likelihood_profile_chi_square.values)
                    if np.any(np.isfinite(c))
                ),
                "ranges (never points)": ", ".join(flat_ranges),
            }
        )
display(pd.DataFrame(rows).round(4).style.hide(axis="index"))

# %% [markdown]
# ### Which reported numbers contradict each other: minimal conflicting subsets
#
# For every inconsistent fit, the smallest sets of the figure's numbers that no parameter set within the
# bounds puts within their reading precision (a set *conflicts* when the best fit to it alone still leaves a
# residual above 1; *minimal*: none of its proper subsets conflicts). Subsets are searched by increasing size
# up to the cap stated in each row; "worst residual" is the smallest worst |residual| any fit to the subset
# reached, and "above_noise" whether its margin over 1 exceeds the residuals' numerical noise (their largest
# change when the sample spacing is halved, at the figure's best fit).

# %%
display(Markdown(f"> {data['joint'].attrs['conflict_method']}"))
display(conflicts.style.format(precision=3).hide(axis="index"))

# %% [markdown]
# ## 2. Residual of every reported number: stated parameters vs the best fit
#
# Grey: the stated parameters (what the claims table shows); blue: the best fit. The band is the reading
# precision; "not produced" marks a number the run cannot produce at all (infeasible, e.g. no stick).

# %%
for name in FIGURES:
    ds = data[name]
    fams = [str(f) for f in ds.family.values]
    fig, axes = plt.subplots(
        1, len(fams), figsize=(5.5 * len(fams), 0.32 * ds.sizes["claim"] + 1.6), sharey=True, squeeze=False
    )
    y = np.arange(ds.sizes["claim"])
    for ax, fam in zip(axes[0], fams):
        sub = ds.sel(family=fam)
        ax.axvspan(-1, 1, color="0.9")
        for values, dy, colour, label in (
            (sub.residual_stated.values, 0.2, "0.6", "stated"),
            (sub.residual.values, -0.2, "tab:blue", "best fit"),
        ):
            ax.barh(y + dy, np.clip(np.nan_to_num(values), -20, 20), height=0.4, color=colour, label=label)
            for k in np.nonzero(~np.isfinite(values))[0]:  # a number the run cannot produce: infeasible
                ax.text(0.3, y[k] + dy, "not produced (infeasible)", color=colour, fontsize=7, va="center")
        ax.set_yticks(y, [str(c) for c in ds.claim.values], fontsize=8)
        ax.set_xlim(-20, 20)
        ax.set_xlabel("(measured − reported) / reading precision (clipped at ±20)")
        verdict = "consistent" if int(sub.consistent) else "inconsistent"
        ax.set_title(f"{fam}: {verdict}", fontsize=10)
    axes[0][0].legend(fontsize=8, loc="lower left")
    fig.suptitle(ds.attrs["title"], fontsize=11)
    fig.tight_layout()
    plt.show()

# %% [markdown]
# Leave-one-out residuals within each figure (linearised at its best fit): a number whose residual grows when
# it is left out is one the figure's other numbers contradict.

# %%
rows = {}
for name in FIGURES:
    if name == "joint":
        continue
    ds = data[name]
    for fam in ds.family.values:
        for claim, value in zip(ds.claim.values, ds.loo_residual.sel(family=fam).values):
            rows.setdefault(str(claim), {"figure": name})[f"LOO {fam}"] = value
display(pd.DataFrame(rows).T.round(2))

# %% [markdown]
# ## 3. One parameter set for Sections 3–5 (joint fit) and the numbers that pull against each other
#
# The joint fit shares the baseline; each figure keeps its stated change (Fig. 5: V_b = 1 mm/s, Fig. 6:
# μ_s = 0.8, Fig. 7: C = 0.1, the sweep values of Figs. 10–14). The leave-one-out residual of a number is its
# residual when the fit does not see it: large ones are the numbers the others contradict.

# %%
joint = data["joint"]
loo = joint.loo_residual.to_pandas().T
loo.columns = [f"LOO {c}" for c in loo.columns]
fitres = joint.residual.to_pandas().T
fitres.columns = [f"fit {c}" for c in fitres.columns]
frame = pd.concat([fitres, loo], axis=1)
reported = numbers[(numbers.figure == "joint")].drop_duplicates("claim").set_index("claim")
frame.insert(
    0, "reported", [f"{reported.loc[c, 'reported']:g} {reported.loc[c, 'unit']}" for c in frame.index]
)
frame.insert(1, "figure", [str(f) for f in joint.claim_figure.values])
display(frame.round(2))
display(Markdown(f"Leave-one-out method: `{joint.loo_residual.attrs.get('comment', '')}`."))

# %% [markdown]
# ## 4. Misprint ranking
#
# **(a) Inferred vs stated** (joint fit): distance of each parameter from its stated value, in units of the
# posterior spread of log10 of the parameter (sampled when the chain is long enough, else the Laplace spread).

# %%
display(ranking.round(4))

# %% [markdown]
# **(b) The alternatives the text allows and single changes**, each on the joint problem with every other
# parameter as stated: σ = 0.3 (text) instead of 0.5 (captions), units converted to SI, Eq. 4's σV_b term as
# printed (without μ_s N), a kinetic coefficient μ_k < μ_s, and each parameter changed alone (scanned over its
# bounds). "reproduced" counts the numbers within their reading precision.

# %%
cols = [
    "family",
    "hypothesis",
    "parameter",
    "value",
    "reproduced",
    "numbers",
    "chi2",
    "worst",
    "worst_claim",
    "z",
]
display(
    hypotheses[cols]
    .sort_values(["family", "reproduced"], ascending=[True, False])
    .round(3)
    .style.hide(axis="index")
)
best = hypotheses[hypotheses.hypothesis != "stated"].sort_values("reproduced", ascending=False)
stated_n = hypotheses[hypotheses.hypothesis == "stated"].set_index("family")["reproduced"]
lines = []
for fam, grp in best.groupby("family"):
    top = grp.iloc[0]
    what = (
        f"changing {top.parameter} alone to {top.value:.3g} (stated {top.stated:g})"
        if top.hypothesis == "single_change"
        else f"the hypothesis *{top.hypothesis}* ({top.description})"
    )
    lines.append(
        f"* **{fam}**: the single change that reproduces most numbers is {what}: {top.reproduced} of "
        f"{top.numbers} within their reading precision (stated parameters: {stated_n.get(fam, 'n/a')})."
    )
display(Markdown("\n".join(lines)))

# %% [markdown]
# ## 5. The consistent regions (corner plots) and the sampler's diagnostics
#
# Samples of log10 of the free parameters (each the set closest to the stated one with its motion); red lines:
# stated values, blue ×: a best-fitting set (on a ridge, one member of it: see the ranges above). The
# diagnostics say how far the chains can be trusted: emcee's integrated autocorrelation time τ should be well
# below the chain length / 50 for a converged posterior. In the default build the chains are short and the
# joint problem is not sampled at all (a cost limit; `inverse.long: true` gives the long run) — there the
# spreads used in the ranking are the Laplace (Gauss-Newton) ones, and the corner plots show where the walkers
# went, not a converged posterior.

# %%
rows = []
for name in FIGURES:
    ds = data[name]
    for fam in ds.family.values:
        sub = ds.sel(family=fam)
        rows.append(
            {
                "figure": name,
                "family": str(fam),
                "steps": float(sub.chain_steps),
                "mean acceptance": float(sub.acceptance_fraction.mean()),
                "max tau": float(sub.autocorr_time.max()),
                "converged (steps >= 50 tau)": bool(sub.chain_converged == 1),
                "infeasible proposals": float(sub.infeasible_fraction),
            }  # (the study's CPU time is in each dataset's cpu_time: a measurement of the machine, not shown)
        )
display(pd.DataFrame(rows).round(3).style.hide(axis="index"))

# %%
for name in settings.get("corner", []):  # the figures whose corner plots this build drew
    for fam in data[name].family.values:
        display(Markdown(f"**{name} / {fam}**"))
        display(Image(filename=paths.inverse_corner(name, fam), width=640))

# %% [markdown]
# ## 6. What the fit shows

# %%
lines = []
for _, r in summary.iterrows():
    sets = conflicts[
        (conflicts.figure == r.figure) & (conflicts.family == r.family) & (conflicts["size"] > 0)
    ]
    clash = "; conflicting: " + " | ".join(sets.claims) if len(sets) else ""
    lines.append(
        f"* {r.figure} / {r.family}: **{r.verdict}** (worst |residual| {r.worst_residual} at "
        f"{r.worst_claim}); {r.identifiable_dimensions} of {r.free_parameters} dimensions identifiable — "
        f"fitted {pairs(r)}{clash}"
    )
display(Markdown("\n".join(lines)))
