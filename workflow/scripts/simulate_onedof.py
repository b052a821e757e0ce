"""Thin wiring: solve every reading x method of one scene and write one dataset each (Snakemake script).

Datasets a claim reads carry a perturbation ensemble (stickslip.ensemble) of the run's own params mapping
(only its reading and method: another method's step settings never make a member that repeats the run). A
run whose oscillation grows without bound is the model's answer (solver_status = 2, outcome = diverged,
with its mechanism); a numerical failure is solver_status = 1, never a result."""

import logging

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import scene_run_dataset
from stickslip.studies.specs import PERTURBED_FIELDS, from_job_params, run_spec

log_to_file(snakemake.log[0])  # noqa: F821
params, scene = snakemake.params, snakemake.params.scene  # noqa: F821
ensemble = EnsembleSpec.from_mapping(params.ensemble).without_blas()  # 1-DOF: no BLAS
for (reading, method), config, path in zip(params.runs, params.configs, snakemake.output, strict=True):  # noqa: F821
    spec = run_spec(OnedofJob.model_validate(config).onedof, scene, reading, method)
    ds = ensemble_dataset(
        from_job_params(lambda onedof, r=reading, m=method: scene_run_dataset(run_spec(onedof, scene, r, m))),
        config,
        ensemble if path in params.ensemble_outputs else None,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    write_dataset(
        ds,
        path,
        scene=spec.scene_attrs(),
        interpretation=spec.interpretation(),
        method={"name": method, **spec.solver_settings, **ds.attrs.pop("solver_run_settings", {})},
        title=f"{spec.figure} {scene}: reading {reading}, method {method}",
    )
    logging.info("%s %s %s: %s", scene, reading, method, ds.attrs.get("solver_message", ""))
