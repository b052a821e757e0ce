"""Thin wiring: Fig. 17's mu(v_r) along the baseline solution -> CSV (the FE friction law) + netCDF."""

import os
from functools import partial

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.studies.onedof import friction_table_from_config
from stickslip.studies.specs import PERTURBED_FIELDS, run_spec

table, config = snakemake.params.table, snakemake.params.config
ensemble = EnsembleSpec.from_mapping(snakemake.params.ensemble).without_blas()  # 1-DOF: no BLAS
ds = ensemble_dataset(
    partial(friction_table_from_config, table=table),
    config,
    ensemble,
    run_id=snakemake.output.nc,
    fields=PERTURBED_FIELDS,
)
tmp = snakemake.output.csv + ".tmp"
with open(tmp, "w") as fh:
    fh.write("relative_velocity_mm_per_s,mu\n")
    for v, m in zip(ds.relative_speed.values, ds.mu.values):
        fh.write(f"{v:.10g},{m:.10g}\n")
os.replace(tmp, snakemake.output.csv)
spec = run_spec(config, table["scene"], table["reading"], table["method"])
write_dataset(
    ds,
    snakemake.output.nc,
    scene=spec.scene_attrs(),
    interpretation=spec.interpretation(),
    method={"name": spec.method, **spec.solver_settings},
    title="Fig. 17: friction coefficient vs relative velocity",
)
