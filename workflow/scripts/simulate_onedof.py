"""Thin wiring: solve every reading x method of one scene and write one dataset each (Snakemake script).

Datasets a claim reads carry a perturbation ensemble (stickslip.ensemble) of the run's own params mapping
(only its reading and method: another method's step settings never make a member that repeats the run). A
run whose oscillation grows without bound is the model's answer (solver_status = 2, outcome = diverged,
with its mechanism); a numerical failure is solver_status = 1, never a result."""

import logging

from stickslip.io.progress import log_to_file
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import scene_run_dataset
from stickslip.studies.specs import job_dataset, run_spec

log_to_file(snakemake.log[0])  # noqa: F821
params, scene = snakemake.params, snakemake.params.scene  # noqa: F821
for (reading, method), config, path in zip(params.runs, params.configs, snakemake.output, strict=True):  # noqa: F821
    spec = run_spec(OnedofJob.model_validate(config).onedof, scene, reading, method)
    build = lambda onedof, r=reading, m=method: scene_run_dataset(run_spec(onedof, scene, r, m))  # noqa: E731
    ds = job_dataset(build, config, params.ensemble, path, path in params.ensemble_outputs)
    title = f"{spec.figure} {scene}: reading {reading}, method {method}"
    spec.write(ds, path, title, method=ds.attrs.pop("solver_run_settings", {}))
    logging.info("%s %s %s: %s", scene, reading, method, ds.attrs.get("solver_message", ""))
