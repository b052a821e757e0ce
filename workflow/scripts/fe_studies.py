"""Sweeps, convergence and stability studies, continuum increments -> results/fe/*.nc (one job)."""

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.fe.params import FrictionTable
from stickslip.fe.quantities import INTERPRETATION
from stickslip.fe.step_halving import apply_step_halving
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import PERTURBED_FIELDS, study_job
from stickslip.studies.fe_convergence import convergence_dataset
from stickslip.studies.fe_increments import increments_dataset
from stickslip.studies.fe_stability import stability_dataset
from stickslip.studies.fe_sweeps import sweep_dataset, sweep_half_step

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
# the studies' sections and base scenes (studies.fe_config.job_config): the ensemble perturbs this mapping,
# each study reads its part of a member typed (study_job), and a dataset records its section as given
params = snakemake.params.config  # noqa: F821
job = FeJob.model_validate(params)
out = snakemake.output  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
ensemble = EnsembleSpec.from_mapping(snakemake.params.ensemble)  # noqa: F821  (claimed: sweeps, stability, increments)
for name, path in zip(snakemake.params.sweeps, out.sweeps, strict=True):  # noqa: F821
    ds = ensemble_dataset(
        lambda c, name=name: sweep_dataset(study_job(c, "sweeps"), name, friction),
        params,
        ensemble,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    ds = apply_step_halving(ds, sweep_half_step(job, name, friction), along=job.sweeps[name].coord)
    method = {"integrator": "central_difference", "sweep": name}
    write_dataset(ds, path, scene=params["sweeps"][name], interpretation=INTERPRETATION, method=method)
    print(
        f"sweep {name} written; not converged at half step: {ds.attrs['step_halving_not_converged']}",
        flush=True,
    )
for kind, build in (("convergence", convergence_dataset), ("stability", stability_dataset)):
    spec = ensemble if kind == "stability" else None  # the convergence study is a spread measurement itself
    ds = ensemble_dataset(
        lambda c, kind=kind, build=build: build(study_job(c, kind), friction),
        params,
        spec,
        run_id=out[kind],
        fields=PERTURBED_FIELDS,
    )
    write_dataset(ds, out[kind], scene=params[kind], interpretation=INTERPRETATION, method={"study": kind})
    print(f"{kind} written", flush=True)
ds = ensemble_dataset(
    lambda c: increments_dataset(study_job(c, "increments")),
    params,
    ensemble,
    run_id=out.increments,
    fields=PERTURBED_FIELDS,
)
write_dataset(
    ds, out.increments, scene=params["increments"], interpretation=INTERPRETATION, method={"kind": "eigen"}
)
