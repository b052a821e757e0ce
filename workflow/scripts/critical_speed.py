"""Thin wiring: continuation over belt speed -> critical speed, one dataset per reading (Snakemake script)."""

import logging
from functools import partial

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import critical_speed_from_config
from stickslip.studies.specs import PERTURBED_FIELDS, baseline_spec, from_job_params

log_to_file(snakemake.log[0])  # noqa: F821
params = snakemake.params  # noqa: F821
onedof = OnedofJob.model_validate(params.config).onedof
ensemble = EnsembleSpec.from_mapping(params.ensemble).without_blas()  # 1-DOF: no BLAS
for reading, path in zip(onedof.critical_speed.readings, snakemake.output, strict=True):  # noqa: F821
    spec = baseline_spec(onedof, reading)
    ds = ensemble_dataset(
        from_job_params(partial(critical_speed_from_config, reading=reading)),
        params.config,
        ensemble if path in params.ensemble_outputs else None,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    write_dataset(
        ds,
        path,
        scene=spec.scene_attrs() | {"continuation": "natural parameter, increasing V_b"},
        interpretation=spec.interpretation(),
        method={"name": spec.method, **spec.solver_settings},
        title=f"Critical belt speed, reading {reading}",
    )
    logging.info(
        "%s: critical speed %s mm/s; failures: %s", reading, float(ds.critical_belt_speed), ds.failures
    )
