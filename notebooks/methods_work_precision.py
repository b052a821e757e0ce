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
# # Speed vs accuracy of integration methods (issue 3)
#
# The paper integrates the single sign() equation with ode45 and claims any standard solver handles
# stick-slip "without need to halt". Here every method is measured against the exact event-driven
# switch solver on the same scenes: error over the whole 40 s run and in the limit-cycle period, versus
# CPU time and RHS evaluations. Failed runs are data: they appear only in the failure map.
# Presentation only: everything is read from `results/methods/*.nc`.

# %%
import glob
import os
import sys

import numpy as np
import xarray as xr

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
CODE = next(
    d
    for d in (os.path.join(HERE, ".."), os.getcwd(), os.path.join(os.getcwd(), ".."))
    if os.path.isdir(os.path.join(d, "workflow", "scripts"))
)
ROOT = os.getcwd() if os.path.isdir(os.path.join(os.getcwd(), "results")) else os.path.abspath(CODE)
sys.path.insert(0, os.path.join(CODE, "workflow", "scripts"))
from methods_plots import failure_map_figure, work_precision_figure  # noqa: E402

files = sorted(glob.glob(os.path.join(ROOT, "results", "methods", "*_work_precision.nc")))
print("scenes:", [os.path.basename(f) for f in files])

# %% [markdown]
# ## Work-precision tables and charts, one per scene
# `cpu_ratio_to_paper` is CPU time divided by sign()+RK45 at rtol 1e-3 (MATLAB ode45 defaults),
# measured in the same run.

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
    lines = [" | ".join(COLS), " | ".join("---" for _ in COLS)]
    for i in range(ds.sizes["run"]):
        row = []
        for c in COLS:
            v = ds[c].values[i]
            row.append(f"{v:.3g}" if isinstance(v, (float, np.floating)) else str(v))
        lines.append(" | ".join(row))
    return "\n".join(lines)


for f in files:
    with xr.open_dataset(f) as ds:
        ds = ds.load()
    name = os.path.basename(f).replace("_work_precision.nc", "")
    print(
        f"\n### {name}: paper's method {ds.attrs['paper_method_cpu_time'] * 1e3:.1f} ms CPU, "
        f"reference period {ds.attrs['reference_period']:.10g} s"
    )
    print(table(ds))
    ex = ds["solver"].values == "exact"
    if ex.any():
        print(f"exact solver speed-up vs paper's method: {1 / ds['cpu_ratio_to_paper'].values[ex][0]:.0f}x")
    work_precision_figure(ds, name)

# %% [markdown]
# ## Pareto-best method per accuracy level
# For each state-error level, the cheapest (CPU) successful run that reaches it.

# %%
for f in files:
    with xr.open_dataset(f) as ds:
        ds = ds.load()
    ok = ds["status"].values == "ok"
    print(os.path.basename(f))
    for level in (1e-1, 1e-2, 1e-3, 1e-4, 1e-6):
        good = ok & (ds["state"].values <= level) & (ds["solver"].values != "exact")
        if good.any():
            i = np.flatnonzero(good)[np.argmin(ds["cpu_time"].values[good])]
            cpu_ms = ds["cpu_time"].values[i] * 1e3
            print(f"  state error <= {level:g}: {ds['label'].values[i]}  ({cpu_ms:.2f} ms)")
        else:
            print(f"  state error <= {level:g}: only the exact solver")

# %% [markdown]
# ## Where methods fail
# Colour = most severe failure per (parameter value, method setting); see `stickslip.analysis.failure`.

# %%
fm = os.path.join(ROOT, "results", "methods", "failure_map.nc")
with xr.open_dataset(fm) as ds:
    ds = ds.load()
failure_map_figure(ds)
kinds = ds["failure_kind"]
print(kinds.to_pandas().T.to_string() if hasattr(kinds, "to_pandas") else kinds)
