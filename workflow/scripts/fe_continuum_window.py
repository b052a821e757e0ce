"""The continuum strip over a claim's window -> results/fe/continuum_window/<scene>.nc (dt and dt/2)."""

from stickslip.fe.params import FrictionTable
from stickslip.fe.quantities import INTERPRETATION
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import window_mapping
from stickslip.studies.fe_continuum import continuum_window_dataset

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
job = FeJob.model_validate(snakemake.params.config)  # noqa: F821  (the scene resolved, the comparison)
scene = snakemake.wildcards.scene  # noqa: F821
mapping = window_mapping(job, scene)
nx, ny = job.comparison.mesh
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
ds = continuum_window_dataset(mapping, friction, nx=nx, ny=ny, name=scene)
print(
    f"{scene}: continuum {nx}x{ny} over {mapping['solver']['t_end']} s, cpu per member "
    f"{[round(float(v), 1) for v in ds['cpu_time_ensemble'].values]} s, "
    f"not converged at half step: {ds.attrs['step_halving_not_converged']}",
    flush=True,
)
out = snakemake.output[0]  # noqa: F821
write_dataset(ds, out, scene=mapping, interpretation=INTERPRETATION, method={"mesh": [nx, ny]})
