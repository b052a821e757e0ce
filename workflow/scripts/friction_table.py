"""Thin wiring: Fig. 17's mu(v_r) along the baseline solution -> CSV (the FE friction law) + netCDF."""

import os

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import friction_table_from_config, friction_table_spec
from stickslip.studies.specs import PERTURBED_FIELDS, from_job_params

params = snakemake.params  # noqa: F821
onedof = OnedofJob.model_validate(params.config).onedof
ensemble = EnsembleSpec.from_mapping(params.ensemble).without_blas()  # 1-DOF: no BLAS
ds = ensemble_dataset(
    from_job_params(friction_table_from_config),
    params.config,
    ensemble,
    run_id=snakemake.output.nc,  # noqa: F821
    fields=PERTURBED_FIELDS,
)
tmp = snakemake.output.csv + ".tmp"  # noqa: F821
with open(tmp, "w") as fh:
    fh.write("relative_velocity_mm_per_s,mu\n")
    for v, m in zip(ds.relative_speed.values, ds.mu.values):
        fh.write(f"{v:.10g},{m:.10g}\n")
os.replace(tmp, snakemake.output.csv)  # noqa: F821
spec = friction_table_spec(onedof)
write_dataset(
    ds,
    snakemake.output.nc,  # noqa: F821
    scene=spec.scene_attrs(),
    interpretation=spec.interpretation(),
    method={"name": spec.method, **spec.solver_settings},
    title="Fig. 17: friction coefficient vs relative velocity",
)
