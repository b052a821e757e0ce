# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Sections 9-12: elastic beam on a rotating rigid disc
# Presentation only: reads the netCDF datasets written by `workflow/rules/fe.smk`, plots them and shows the
# claims of `config/claims/sections_09_12.yaml` next to the measured values.

# %%
from pathlib import Path

import matplotlib.pyplot as plt
import xarray as xr
import yaml

FE = Path("results/fe")
SCENES = [
    "section9_kinematic_0p5mm_s",
    "section9_kinematic_15p2rpm",
    "section10_fixed_normal_0p5mm_s",
    "section11_penalty_15p2rpm",
    "section11_penalty_0p5mm_s",
    "section12_angle30_15p2rpm",
]
ds = {s: xr.load_dataset(FE / f"{s}.nc") for s in SCENES if (FE / f"{s}.nc").exists()}
print(next(iter(ds.values())).attrs.get("model_interpretation", ""))

# %% [markdown]
# ## Node-1 displacements and velocities per scene (Figs. 21, 23-25, 27-30, 32-33, 35-36)

# %%
for name, d in ds.items():
    fig, ax = plt.subplots(1, 3, figsize=(13, 2.8))
    d.horizontal_displacement.plot(ax=ax[0], lw=0.5, label="horizontal")
    d.vertical_displacement.plot(ax=ax[0], lw=0.5, label="vertical")
    d.horizontal_velocity.plot(ax=ax[1], lw=0.5, label="horizontal")
    d.vertical_velocity.plot(ax=ax[1], lw=0.5, label="vertical")
    d.contact_state.plot(ax=ax[2], lw=0.5)
    for a in ax:
        a.set_title("")
    ax[0].legend(fontsize=7)
    fig.suptitle(name)
    plt.show()
    print(
        {
            k: float(d[k])
            for k in (
                "dominant_frequency",
                "horizontal_amplitude",
                "vertical_amplitude",
                "stick_fraction",
                "slip_fraction",
                "separation_fraction",
                "stable_time_step",
                "increment_count_0p65s",
            )
        }
    )

# %% [markdown]
# ## Sweeps: contact angle (Section 12) and penalty stiffness (Section 11)

# %%
for sweep, coord in (("angle_sweep", "contact_angle"), ("penalty_sweep", "penalty_stiffness")):
    p = FE / f"{sweep}.nc"
    if not p.exists():
        continue
    d = xr.load_dataset(p)
    fig, ax = plt.subplots(1, 3, figsize=(13, 2.8))
    d.horizontal_amplitude.plot(ax=ax[0], marker="o")
    d.max_abs_horizontal_velocity.plot(ax=ax[1], marker="o")
    d.stable_time_step.plot(ax=ax[2], marker="o")
    if coord == "penalty_stiffness":
        for a in ax:
            a.set_xscale("log")
    plt.show()

# %% [markdown]
# ## Convergence with the element count and stability of steady sliding

# %%
if (FE / "convergence.nc").exists():
    print(xr.load_dataset(FE / "convergence.nc").to_dataframe())
if (FE / "stability.nc").exists():
    st = xr.load_dataset(FE / "stability.nc")
    st.max_growth_rate.plot(x="friction_slope", y="contact_angle")
    plt.show()
    print(
        st[
            [
                "crosscheck_angle",
                "crosscheck_slope",
                "crosscheck_eigen_growth_rate",
                "crosscheck_transient_growth_rate",
            ]
        ].to_dataframe()
    )

# %% [markdown]
# ## Claims: paper vs measured

# %%
rows = yaml.safe_load(Path("config/claims/sections_09_12.yaml").read_text())


def measured(ref):
    if "dataset" in ref and Path(ref["dataset"]).exists():
        return float(xr.load_dataset(ref["dataset"])[ref["variable"]])
    return ref.get("value")


for r in rows:
    if r["kind"] == "value":
        m = measured(r)
        print(f"{r['id']:45s} paper={r['value']!s:>10} measured={m:.4g}  expected={r['expected']}")
    elif r["kind"] == "compare":
        lhs, rhs = measured(r["lhs"]), measured(r["rhs"])
        print(f"{r['id']:45s} {lhs:.4g} {r['relation']} {rhs:.4g}  expected={r['expected']}")
    else:
        print(
            f"{r['id']:45s} trend of {r['variable']} along {r['coord']} (paper sign {r['sign']})  "
            f"expected={r['expected']}"
        )
