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
# # Section 3 — the baseline: Figures 2 and 3
#
# The paper's baseline mass on a moving belt: M = 1 kg, K = 5 N/mm, C = 1.5, μ_s = 0.5, N = 10 N,
# V_b = 0.5 mm/s, x0 = 0, v0 = 0.5 mm/s, with σ = 0.3 in the text and σ = 0.5 in the caption.
# Each figure is reproduced for every *reading* of the paper's equations:
#
# | reading | friction law | σ |
# |---|---|---|
# | `consistent_caption` / `consistent_text` | pulls toward the belt velocity: μ_s(1 − σ\|v_r\|) | 0.5 / 0.3 |
# | `eq3_caption` / `eq3_text` | Eq. 3 exactly as printed: F = μ_s N (sgn(v_r) − σ v_r) | 0.5 / 0.3 |
# | `eq4_caption` / `eq4_text` | Eq. 4 exactly as printed (σ V_b term lacks μ_s N) | 0.5 / 0.3 |
#
# Solid lines: the exact event-driven solver (the reference). Dashed: the paper's method, the sign()
# right-hand side with RK45 at ode45's default tolerances. Dotted black lines mark numbers the paper reports.
# This notebook only presents: every number comes from `results/` and was computed by the pipeline.

# %%
import matplotlib.pyplot as plt
from IPython.display import Markdown, display

from stickslip import catalogue as paths
from stickslip.io.netcdf import read_dataset
from stickslip.presentation.notebook import claims_frame, scorecard, verdicts
from stickslip.presentation.plots import mark_reported

PARAMS = globals().get("PARAMS", {})  # injected by the pipeline; defaults for a standalone run
FIG2 = PARAMS.get("figures", {}).get(
    "fig02",
    {
        "readings": [
            "consistent_caption",
            "consistent_text",
            "eq3_caption",
            "eq3_text",
            "eq4_caption",
            "eq4_text",
        ],
        "methods": ["exact", "ode45"],
    },
)
READINGS = FIG2["readings"]
data = {(r, m): read_dataset(paths.onedof_dataset("fig02", r, m)) for r in READINGS for m in FIG2["methods"]}
STYLES = {"exact": dict(color="C0", lw=1.5), "ode45": dict(color="C3", lw=0.9, ls="--")}
claims = claims_frame(paths.claims_table(), sections=["3", "5"])
claims = claims[claims["figure"].str.startswith("Fig. 2") | claims["figure"].str.startswith("Fig. 3")]

# %% [markdown]
# ## Scorecard: Figures 2 and 3
#
# The paper's statements checked against every reading: counts per status, then each check with the number
# the paper reports, the measured one, its `margin` to the claim's threshold and its `spread` over a
# perturbation ensemble (runs that must not differ). A margin within 3 spreads is *indistinguishable*: the
# pipeline's own numerical noise could decide it, so it is called neither reproduced nor deviating.

# %%
display(verdicts([2, 3]))
display(scorecard(claims, "Section 3 claims: Figures 2 and 3 (incl. their restatements in Section 5)"))

# %% [markdown]
# ## Figure 2 — displacement and velocity versus time

# %%
fig, axes = plt.subplots(len(READINGS), 2, figsize=(12, 2.3 * len(READINGS)), sharex=True, squeeze=False)
for row, reading in zip(axes, READINGS):
    for method, style in STYLES.items():
        if (reading, method) not in data:
            continue
        ds = data[reading, method]
        if int(ds.solver_status) != 0:
            row[0].text(0.05, 0.5, f"{method} failed: not a result", transform=row[0].transAxes, color="red")
            continue
        row[0].plot(ds.time, ds.displacement, label=method, **style)
        row[1].plot(ds.time, ds.velocity, label=method, **style)
    mark_reported(row[0], y=1.5, label="paper: max 1.5 mm")
    mark_reported(row[1], y=1.5, label="paper: max 1.5 mm/s")
    row[0].set_ylabel(f"{reading}\nx [mm]", fontsize=8)
    row[1].set_ylabel("dx/dt [mm/s]")
axes[0, 0].legend(fontsize=8)
axes[-1, 0].set_xlabel("time [s]")
axes[-1, 1].set_xlabel("time [s]")
fig.tight_layout()

# %% [markdown]
# ## Figure 3 — phase plot

# %%
fig, axes = plt.subplots(2, 3, figsize=(12, 7), squeeze=False)
for ax, reading in zip(axes.flat, READINGS):
    for method, style in STYLES.items():
        if (reading, method) not in data:
            continue
        ds = data[reading, method]
        if int(ds.solver_status) == 0:
            ax.plot(ds.displacement, ds.velocity, label=method, **style)
    mark_reported(ax, x=1.4, label="paper: stick ends 1.4 mm")
    mark_reported(ax, x=0.75, label="paper: max speed at 0.75 mm")
    ax.set_title(reading, fontsize=9)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("dx/dt [mm/s]")
axes.flat[0].legend(fontsize=8)
fig.tight_layout()

# %% [markdown]
# ## What the readings show
#
# * **Printed sign (Eq. 3 and Eq. 4):** friction pushes the mass *away* from the belt velocity, so v_r = 0
#   repels and the mass never sticks; it slides backwards and settles at rest at x = −(μ_s N − κ V_b)/K.
#   No stick-slip at all — the printed equations cannot have produced the paper's figures.
# * **Consistent sign, σ = 0.3 (text):** C = σ μ_s N exactly, so the slip phase has *zero* effective damping;
#   stick ends where the slip equilibrium lies (x = 0.85 mm) and the orbit is a harmonic oscillation that
#   grazes the belt velocity once per period (stick time 0, f = √5/2π = 0.356 Hz).
# * **Consistent sign, σ = 0.5 (caption):** negative slip damping (C − σ μ_s N = −1) gives a genuine
#   stick-slip limit cycle, reached after the first stick. This is the *primary reading* (declared by the rule
#   in docs/READINGS.md, not chosen by its score); the verdicts table above gives each figure's verdict in it,
#   as printed, and the best of the readings (a search).

# %%
exact = data.get(("consistent_caption", "exact"))
if exact is not None:
    display(
        Markdown(
            f"Consistent reading, σ = 0.5: stick {float(exact.stick_time):.3f} s, "
            f"slip {float(exact.slip_time):.3f} s, frequency {float(exact.frequency_peaks):.4f} Hz "
            f"(spectrum {float(exact.frequency_spectrum):.4f} Hz), "
            f"peak-to-peak {float(exact.amplitude_peak_to_peak):.3f} mm, "
            f"max |v| {float(exact.max_speed):.3f} mm/s."
        )
    )
