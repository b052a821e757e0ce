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
# # Interpretation study — which reading of the paper reproduces what it reports
#
# The paper's equations and numbers are not mutually consistent, so every figure is computed for several
# *readings* (see the README): the printed sign of Eq. 3 and Eq. 4, a physically consistent sign (friction
# drives the mass toward the belt velocity), each with σ = 0.3 (text) or σ = 0.5 (captions), the consistent
# sign with the friction levelling off at 0.6 mm/s (Fig. 17's plateau), and the consistent sign in SI units.
# Nothing is tuned to hit the paper's numbers; instead every claim is checked against every reading.
#
# This notebook shows
#
# 1. the ranking of the readings by the claims they reproduce (`results/claims/reading_ranking.csv`);
# 2. how each reading fares per paper section (from `results/claims/deviations.csv`);
# 3. the claims that *no* reading reproduces, with the reason (`results/claims/unreproduced_claims.csv`);
# 4. the Section 13 conclusion "as the sliding speed increases there is a critical speed when stick slip
#    vibration disappear": the critical belt speed per reading (`results/onedof/critical_speed.csv`).
#
# This notebook only presents: every number comes from `results/` and was computed by the pipeline.

# %%
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from IPython.display import Markdown, display

from stickslip import catalogue as paths
from stickslip.claims.rows import STATUSES
from stickslip.io.netcdf import read_dataset
from stickslip.presentation.notebook import (
    claims_frame,
    claims_readings,
    scorecard,
    status_counts,
    styled_claims,
    verdicts,
)
from stickslip.presentation.plots import STATUS_COLOUR, reading_colours

PARAMS = globals().get("PARAMS", {})  # injected by the pipeline; defaults for a standalone run
READINGS = claims_readings(PARAMS)
CRIT_READINGS = PARAMS.get("critical_speed_readings") or READINGS
ranking = pd.read_csv(paths.reading_ranking("csv"))
unreproduced = pd.read_csv(paths.unreproduced_claims())
critical = pd.read_csv(paths.critical_speed_summary("csv"))
deviations = claims_frame(paths.claims_table())
continuation = {r: read_dataset(paths.critical_speed(r)) for r in CRIT_READINGS}

# %% [markdown]
# ## Scorecard: every claim of the paper
#
# All claim checks of all sections, per reading (`-`: claims that do not depend on the reading): counts per
# status, then each check with its `margin` to the claim's threshold and its `spread` over a perturbation
# ensemble. A margin within 3 spreads is *indistinguishable*: the pipeline's own numerical noise could decide
# it, so it is called neither reproduced nor deviating (and is not counted as comparable below).

# %%
display(verdicts(list(range(2, 18))))
display(scorecard(deviations, "All claims of the paper"))

# %% [markdown]
# ## 1. Ranking of the readings
#
# Counts of claim checks per reading (a claim that refers to a per-reading dataset is checked once per
# reading; claims about reading-independent results, e.g. Eq. 6, have no reading and are not counted). The
# last column is reproduced / (reproduced + deviates): the share of the comparable claims a reading gets
# right (an indistinguishable check is decided neither way, so it is not comparable).

# %%
display(
    ranking.style.background_gradient(
        subset=["reproduced_fraction_of_comparable"], cmap="Greens", vmin=0, vmax=1
    )
    .format({"reproduced_fraction_of_comparable": "{:.1%}"})
    .hide(axis="index")
)
fig, ax = plt.subplots(figsize=(9, 0.45 * len(ranking) + 1.2))
left = np.zeros(len(ranking))
for status in STATUSES:
    vals = ranking[status].to_numpy(dtype=float)
    ax.barh(ranking["reading"], vals, left=left, color=STATUS_COLOUR[status], edgecolor="0.4", label=status)
    for y, (x0, v) in enumerate(zip(left, vals)):
        if v:
            ax.text(x0 + v / 2, y, f"{int(v)}", ha="center", va="center", fontsize=8)
    left += vals
ax.invert_yaxis()
ax.set_xlabel("claim checks")
ax.set_title("readings ranked by reproduced claims (best first)", fontsize=10)
ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
fig.tight_layout()

# %% [markdown]
# ## 2. Reproduced claims per section and reading
#
# Each cell: reproduced / comparable (reproduced + deviates) claim checks; colour = share reproduced
# (grey: nothing comparable). The last column holds the claims that do not depend on the reading (Eq. 6,
# the beam-on-disc scenes of Sections 9–12).

# %%
comparable = deviations[deviations["status"].isin(["reproduced", "deviates"])]
rep_counts = comparable.pivot_table(
    index="section",
    columns="reading",
    values="status",
    aggfunc=lambda s: int((s == "reproduced").sum()),
    fill_value=0,
)
cmp_counts = comparable.pivot_table(
    index="section", columns="reading", values="status", aggfunc="count", fill_value=0
)
order = [r for r in ranking["reading"] if r in cmp_counts.columns] + (
    ["-"] if "-" in cmp_counts.columns else []
)
sections = sorted(cmp_counts.index, key=lambda s: float(s) if s.replace(".", "").isdigit() else 99)
rep_counts = rep_counts.reindex(index=sections, columns=order, fill_value=0)
cmp_counts = cmp_counts.reindex(index=sections, columns=order, fill_value=0)
share = np.where(cmp_counts > 0, rep_counts / cmp_counts.where(cmp_counts > 0, 1), np.nan)
fig, ax = plt.subplots(figsize=(1.1 * len(order) + 2, 0.5 * len(sections) + 1.5))
cmap = plt.get_cmap("RdYlGn").copy()
cmap.set_bad("0.85")
im = ax.imshow(np.ma.masked_invalid(share), cmap=cmap, vmin=0, vmax=1, aspect="auto")
for i in range(len(sections)):
    for j in range(len(order)):
        ax.text(j, i, f"{rep_counts.iat[i, j]}/{cmp_counts.iat[i, j]}", ha="center", va="center", fontsize=8)
names = ["reading-independent" if r == "-" else r for r in order]
ax.set_xticks(range(len(order)), names, rotation=35, ha="right", fontsize=8)
ax.set_yticks(range(len(sections)), [f"Section {s}" for s in sections], fontsize=8)
fig.colorbar(im, ax=ax, label="share of comparable claims reproduced")
fig.tight_layout()

# %% [markdown]
# ## 3. Claims that no reading reproduces
#
# For each: the statuses it gets across the readings and why it cannot be reproduced.

# %%
display(Markdown(f"**{len(unreproduced)} claims are reproduced by no reading.**"))
display(
    unreproduced[["claim", "figure", "statuses", "why", "quote"]]
    .style.set_properties(subset=["why", "quote"], **{"white-space": "pre-wrap", "text-align": "left"})
    .set_properties(subset=["claim"], **{"background-color": STATUS_COLOUR["deviates"]})
    .hide(axis="index")
)

# %% [markdown]
# ## 4. Section 13 — is there a critical belt speed?
#
# Continuation over belt speed with the exact solver (each run starts from the previous one's end state, belt
# speed increasing): the fraction of the steady window spent sticking and the peak-to-peak amplitude. The
# critical speed (dotted line, where given) is the first speed beyond which no sticking remains. Failed or
# diverging runs are not drawn as values: they are marked by red ticks on the bottom edge.

# %%
colours = reading_colours(list(continuation))
fig, (ax_s, ax_a) = plt.subplots(2, 1, figsize=(13, 7), sharex=True, layout="constrained")
for r, ds in continuation.items():
    vb = ds.belt_velocity.values
    ok = ds.solver_ok.values == 1
    nfail = int((~ok).sum())
    label = r + (f" ({nfail} runs failed – not results)" if nfail else "")
    ax_s.plot(vb[ok], ds.stick_fraction.values[ok], ".-", color=colours[r], label=label)
    ax_a.plot(vb[ok], ds.amplitude_peak_to_peak.values[ok], ".-", color=colours[r])
    if nfail:
        for ax in (ax_s, ax_a):
            ax.plot(
                vb[~ok], np.zeros(nfail), "|", color="red", ms=12, mew=2, transform=ax.get_xaxis_transform()
            )
    vc = float(ds.critical_belt_speed)
    if np.isfinite(vc) and vc > 0:
        for ax in (ax_s, ax_a):
            ax.axvline(vc, color=colours[r], ls=":", lw=1.2)
ax_s.set_xscale("log")
ax_s.set_ylabel("stick fraction (steady window)")
ax_a.set_ylabel("x peak-to-peak [mm]")
ax_a.set_xlabel("belt speed V_b [mm/s] (continuation, increasing)")
fig.legend(*ax_s.get_legend_handles_labels(), fontsize=7, loc="outside right center")
ax_s.set_title("Section 13: 'there is a critical speed when stick slip vibration disappear'", fontsize=10)

# %%
crit = critical.rename(
    columns={
        "critical_belt_speed_mm_per_s": "critical V_b [mm/s]",
        "steady_sliding_stable_from_mm_per_s": "steady sliding stable from [mm/s]",
    }
)


def verdict_colour(v):
    if str(v).startswith("stick-slip disappears"):
        return f"background-color: {STATUS_COLOUR['reproduced']}"
    if str(v).startswith("undetermined"):
        return f"background-color: {STATUS_COLOUR['not-comparable']}"
    return f"background-color: {STATUS_COLOUR['deviates']}"


display(crit.style.map(verdict_colour, subset=["verdict"]).format(precision=4, na_rep="–").hide(axis="index"))

# %% [markdown]
# The Section 13 rows of the claims table (the critical speed and the parameter trends the conclusions
# restate):

# %%
s13 = deviations[deviations["section"] == "13"]
display(status_counts(s13))
display(styled_claims(s13))

# %% [markdown]
# ## What the readings show

# %%
best, worst = ranking.iloc[0], ranking.iloc[-1]
found = critical[
    np.isfinite(critical["critical_belt_speed_mm_per_s"]) & (critical["critical_belt_speed_mm_per_s"] > 0)
]
found = found[~np.isinf(found["critical_belt_speed_mm_per_s"])]
never = critical[critical["critical_belt_speed_mm_per_s"] == 0]["reading"].tolist()
undetermined = critical[critical["critical_belt_speed_mm_per_s"].isna()]["reading"].tolist()
display(
    Markdown(
        f"""
* **Reading that reproduces most (a search over {len(ranking)} readings, not the verdict: each figure's verdict
  is given in the primary reading declared in docs/READINGS.md): `{best["reading"]}`** — {best["reproduced"]} reproduced, {best["deviates"]} deviating,
  {best["indistinguishable"]} indistinguishable, {best["not-comparable"]} not comparable
  ({best["reproduced_fraction_of_comparable"]:.0%} of the comparable checks).
  Last by reproduced count: `{worst["reading"]}` ({worst["reproduced"]} reproduced; its
  {worst["not-comparable"]} not-comparable checks are runs that failed or have nothing to measure, so its
  share of comparable checks, {worst["reproduced_fraction_of_comparable"]:.0%}, rests on few rows).
* **No reading reproduces everything:** {len(unreproduced)} claims are reproduced by none of the
  {len(ranking)} readings (table in part 3) — the paper's numbers contradict each other or its equations.
* **Critical belt speed:** found in {len(found)} readings ("""
        + ", ".join(
            f"{r} {v:.3g} mm/s" for r, v in zip(found["reading"], found["critical_belt_speed_mm_per_s"])
        )
        + f"""); no stick-slip to lose at any swept speed in {", ".join(never) or "none"}; undetermined in
  {", ".join(undetermined) or "none"} (see the verdict column).
"""
    )
)
