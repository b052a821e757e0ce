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
# # Speed vs accuracy of integration methods
#
# The paper integrates the single sign() equation with ode45 and claims any standard solver handles
# stick-slip "without need to halt". Here every method is measured against the exact event-driven
# switch solver on the same scenes: error over the whole 40 s run and in the limit-cycle period, versus
# CPU time and RHS evaluations. Failed runs are data: they appear only in the failure map.
# Presentation only: everything is read from `results/methods/*.nc`.

# %%
import glob
import os

import numpy as np
import pandas as pd
import xarray as xr
from IPython.display import HTML, Image, Markdown, display

from stickslip import catalogue as paths
from stickslip.presentation.notebook import SUMMARY_STYLE
from stickslip.presentation.plots import STATUS_COLOUR

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
ROOT = os.getcwd() if os.path.isdir(paths.RESULTS) else os.path.abspath(os.path.join(HERE, ".."))


def show(figure):
    """The pipeline's own chart (rule methods_figures): drawn once, shown here."""
    display(Image(filename=os.path.join(ROOT, paths.figure("methods", figure))))


files = sorted(glob.glob(os.path.join(ROOT, paths.methods_work_precision("*"))))
display(Markdown("Scenes: " + ", ".join(f"`{os.path.basename(f)}`" for f in files)))

# %% [markdown]
# ## Verdict: the cheapest method at each accuracy level
# For each state-error level, the cheapest (CPU) successful run that reaches it; the tables and charts below
# give every run.

# %%
LEVELS = (1e-1, 1e-2, 1e-3, 1e-4, 1e-6)
best = {}
for f in files:
    with xr.open_dataset(f) as ds:
        ds = ds.load()
    ok = ds["status"].values == "ok"
    column = {}
    for level in LEVELS:
        good = ok & (ds["state"].values <= level) & (ds["solver"].values != "exact")
        if good.any():
            i = np.flatnonzero(good)[np.argmin(ds["cpu_time"].values[good])]
            column[f"state error <= {level:g}"] = (
                f"{ds['label'].values[i]} ({ds['cpu_time'].values[i] * 1e3:.2f} ms)"
            )
        else:
            column[f"state error <= {level:g}"] = "only the exact solver"
    best[os.path.basename(f).replace("_work_precision.nc", "")] = column
cells = [v for column in best.values() for v in column.values()]
sign_best = sum(v.startswith("sign_rk") for v in cells)
display(
    Markdown(
        f"**The sign() formulation (the paper's method, at any tolerance) is the cheapest at {sign_best} of "
        f"{len(cells)} (scene, accuracy) cells.**"
    )
)
display(pd.DataFrame(best).style.set_properties(**{"text-align": "left"}))

# %% [markdown]
# ## Work-precision tables and charts, one per scene
# `cpu_ratio_to_paper` is CPU time divided by sign()+RK45 at rtol 1e-3 (MATLAB ode45 defaults),
# measured in the same run. A failed run (red) is listed with the kind of failure, never drawn as a result.

# %%
COLS = [
    "label",
    "state",
    "period_error",
    "amplitude_error",
    "cpu_time",
    "rhs_evaluations",
    "cpu_ratio_to_paper",
    "status",
    "failure_kind",
]


def table(ds):
    """The scene's runs as a table, failed runs in red."""
    frame = pd.DataFrame({c: ds[c].values for c in COLS})

    def colour(row):
        bad = row["status"] != "ok"
        return [f"background-color: {STATUS_COLOUR['deviates']}" if bad else ""] * len(row)

    return (
        frame.style.apply(colour, axis=1)
        .format({c: "{:.3g}" for c in COLS[1:7]}, na_rep="–")
        .set_table_styles([{"selector": "", "props": [("font-size", "0.85em")]}])
        .hide(axis="index")
    )


for f in files:
    with xr.open_dataset(f) as ds:
        ds = ds.load()
    name = os.path.basename(f).replace("_work_precision.nc", "")
    ex = ds["solver"].values == "exact"
    speedup = (
        f"; the exact solver is {1 / ds['cpu_ratio_to_paper'].values[ex][0]:.0f}x faster" if ex.any() else ""
    )
    display(
        Markdown(
            f"### {name}\n\nThe paper's method takes {ds.attrs['paper_method_cpu_time'] * 1e3:.1f} ms CPU"
            f"{speedup}; reference period {ds.attrs['reference_period']:.10g} s."
        )
    )
    show(f"{name}_work_precision")
    display(
        HTML(
            f"<details><summary style='{SUMMARY_STYLE}'>the {ds.sizes['run']} runs of {name} "
            f"({int((ds['status'].values != 'ok').sum())} failed, in red)</summary>"
            + table(ds).to_html()
            + "</details>"
        )
    )

# %% [markdown]
# ## Where methods fail
# Colour = most severe failure per (parameter value, method setting); see `stickslip.analysis.failure`.

# %%
fm = os.path.join(ROOT, paths.methods_failure_map())
with xr.open_dataset(fm) as ds:
    ds = ds.load()
show("failure_map")
kinds = ds["failure_kind"]
if hasattr(kinds, "to_pandas"):
    display(kinds.to_pandas().T)
