"""Thin wiring: Fig. 17's mu(v_r) along the baseline solution -> CSV (the FE friction law) + netCDF."""

from stickslip.io.text_files import write_text_atomic
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import friction_table_from_config, friction_table_spec
from stickslip.studies.specs import job_dataset

params, output = snakemake.params, snakemake.output  # noqa: F821
ds = job_dataset(friction_table_from_config, params.config, params.ensemble, output.nc)
rows = "".join(f"{v:.10g},{m:.10g}\n" for v, m in zip(ds.relative_speed.values, ds.mu.values))
write_text_atomic(output.csv, "relative_velocity_mm_per_s,mu\n" + rows)
spec = friction_table_spec(OnedofJob.model_validate(params.config).onedof)
spec.write(ds, output.nc, "Fig. 17: friction coefficient vs relative velocity")
