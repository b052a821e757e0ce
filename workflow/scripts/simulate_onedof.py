"""Thin wiring: solve every reading x method of one scene and write one dataset each (Snakemake script).

Datasets a claim reads carry a perturbation ensemble (stickslip.ensemble). A run whose oscillation grows
without bound is the model's answer (solver_status = 2, outcome = diverged, with its mechanism); a numerical
failure is solver_status = 1, never a result."""

import logging

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.studies.onedof import scene_run_dataset
from stickslip.studies.specs import PERTURBED_FIELDS, run_config, run_spec

log_to_file(snakemake.log[0])  # noqa: F821
config, scene = snakemake.params.config, snakemake.params.scene
ensemble = EnsembleSpec.from_mapping(snakemake.params.ensemble).without_blas()  # 1-DOF: no BLAS
for (reading, method), path in zip(snakemake.params.runs, snakemake.output):
    spec = run_spec(config, scene, reading, method)
    claimed = path in snakemake.params.ensemble_outputs
    ds = ensemble_dataset(
        lambda cfg, r=reading, m=method: scene_run_dataset(run_spec(cfg, scene, r, m)),
        run_config(config, reading, method),
        ensemble if claimed else None,
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
