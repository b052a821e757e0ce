"""Every paper scene under one FE reading -> results/fe/<reading>/<scene>.nc (each with its perturbation
ensemble), plus the cross-scene ratios."""

from dataclasses import replace

from stickslip.ensemble import EnsembleSpec, ensemble_dataset, step_member_values
from stickslip.fe.params import FrictionTable
from stickslip.fe.quantities import INTERPRETATION
from stickslip.fe.step_halving import HALF_STEP, apply_step_halving
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import PERTURBED_FIELDS, as_mapping
from stickslip.studies.fe_cross_scene import cross_scene_dataset
from stickslip.studies.fe_scene import scene_dataset

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
job = FeJob.model_validate(snakemake.params.config)  # noqa: F821  (this reading's scenes, resolved)
reading = snakemake.wildcards.fe_reading  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
# the ensemble's second step size is the step-halving run (one run at dt/2 serves both); a scene's
# dataset is bit-identical under any BLAS thread count (tests/fe/test_blas_independence.py), so the BLAS
# member would only repeat the base run
spec = replace(EnsembleSpec.from_mapping(snakemake.params.ensemble).without_blas(), step_factor=HALF_STEP)  # noqa: F821
built, mappings = {}, {}
scene_paths = dict(zip(snakemake.params.scenes, snakemake.output.scenes, strict=True))  # noqa: F821
for name, path in scene_paths.items():
    mappings[name] = as_mapping(job.scenes[name])
    ds = ensemble_dataset(
        lambda mp, n=name: scene_dataset(mp, friction, n),
        mappings[name],
        spec,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    ds = apply_step_halving(ds, step_member_values(ds))
    ds.attrs["fe_reading"] = reading
    print(
        f"{reading}/{name}: {ds.attrs['method']}, cpu={float(ds['cpu_time']):.2f} s, "
        f"not converged at half step: {ds.attrs['step_halving_not_converged']}",
        flush=True,
    )
    built[name] = ds
cross = cross_scene_dataset(built, job.cross_scene)
# Written only once every scene is computed: a job killed while integrating leaves no dataset behind.
for name, path in scene_paths.items():
    method = {"fe_reading": reading}
    write_dataset(built[name], path, scene=mappings[name], interpretation=INTERPRETATION, method=method)
write_dataset(
    cross,
    snakemake.output.cross,  # noqa: F821
    scene=job.cross_scene,
    interpretation=INTERPRETATION,
    method={"kind": "ratio", "fe_reading": reading},
)
