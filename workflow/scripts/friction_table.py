"""Thin wiring: Fig. 17's mu(v_r) along the baseline solution -> CSV (the FE friction law) + netCDF."""

import numpy as np
import xarray as xr

from stickslip.analysis.friction_curve import friction_along_solution, friction_table
from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.io.scenes import run_spec

cfg = snakemake.params.table
spec = run_spec(snakemake.params.config, cfg["scene"], cfg["reading"], cfg["method"])
ds = read_dataset(snakemake.input[0])
law = spec.model.friction
speed, mu = friction_along_solution(
    ds.velocity.values, ds.belt_velocity.values, ds.phase.values, law, spec.params.normal_force
)
table_v, table_mu = friction_table(speed, mu, spec.params.mu_s, int(cfg["bins"]))
with open(snakemake.output.csv + ".tmp", "w") as fh:
    fh.write("relative_velocity_mm_per_s,mu\n")
    for v, m in zip(table_v, table_mu):
        fh.write(f"{v:.10g},{m:.10g}\n")
import os  # noqa: E402

os.replace(snakemake.output.csv + ".tmp", snakemake.output.csv)
out = xr.Dataset(
    {
        "mu": ("relative_speed", table_mu, {"units": "1", "long_name": "friction coefficient |F|/N"}),
        "sample_relative_speed": (
            "sample",
            speed,
            {"units": "mm s-1", "long_name": "|v_r| of each slip sample"},
        ),
        "sample_mu": ("sample", mu, {"units": "1", "long_name": "|F|/N of each slip sample"}),
        "max_relative_speed": (
            (),
            float(np.max(speed)) if len(speed) else np.nan,
            {"units": "mm s-1", "long_name": "largest relative speed along the solution"},
        ),
        "mu_at_max_relative_speed": (
            (),
            float(table_mu[-1]),
            {"units": "1", "long_name": "friction coefficient at the largest relative speed"},
        ),
        "mu_static": ((), spec.params.mu_s, {"units": "1", "long_name": "static friction coefficient"}),
    },
    coords={
        "relative_speed": (
            "relative_speed",
            table_v,
            {"units": "mm s-1", "long_name": "relative speed |v_r|"},
        )
    },
)
write_dataset(
    out,
    snakemake.output.nc,
    scene=spec.scene_attrs(),
    interpretation=spec.interpretation(),
    method={"name": spec.method, **spec.solver_settings},
    title="Fig. 17: friction coefficient vs relative velocity",
)
