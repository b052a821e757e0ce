"""FIT of the tip support to Fig. 21's centre on one penalty scene -> results/fe/<fit>.nc, with its
perturbation ensemble; the ensemble's second step size is the step-halving run."""

from dataclasses import replace

from stickslip.ensemble import EnsembleSpec, ensemble_dataset, step_member_values
from stickslip.fe.params import FrictionTable
from stickslip.fe.step_halving import HALF_STEP, apply_step_halving
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import PERTURBED_FIELDS
from stickslip.studies.fe_setup_fit import setup_fit_dataset, setup_fit_mapping

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
par = snakemake.params  # noqa: F821
job = FeJob.model_validate(par.config)  # the base scene, resolved (studies.fe_config.job_config)
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
# the ensemble's second step size is the step-halving run (one run at dt/2 serves both); a scene's
# dataset is bit-identical under any BLAS thread count (tests/fe/test_blas_independence.py), so the BLAS
# member would only repeat the base run
spec = replace(EnsembleSpec.from_mapping(par.ensemble).without_blas(), step_factor=HALF_STEP)
fit, k = setup_fit_mapping(job, par.base, par.centre)
out = snakemake.output[0]  # noqa: F821
ds = ensemble_dataset(
    lambda mp: setup_fit_dataset(mp, friction, k), fit, spec, run_id=out, fields=PERTURBED_FIELDS
)
ds = apply_step_halving(ds, step_member_values(ds))
write_dataset(ds, out, scene=fit, interpretation=ds.attrs["model_interpretation"], method={"kind": "fit"})
print(
    f"setup fit on {par.base}: tip support {k:.4g} N/mm; not converged at half step: "
    f"{ds.attrs['step_halving_not_converged']}"
)
