"""Thin wiring: continuation over belt speed -> critical speed, one dataset per reading (Snakemake script)."""

import logging
from functools import partial

from stickslip.io.progress import log_to_file
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import critical_speed_from_config
from stickslip.studies.specs import baseline_spec, job_dataset

log_to_file(snakemake.log[0])  # noqa: F821
params = snakemake.params  # noqa: F821
onedof = OnedofJob.model_validate(params.config).onedof
for reading, path in zip(onedof.critical_speed.readings, snakemake.output, strict=True):  # noqa: F821
    build = partial(critical_speed_from_config, reading=reading)
    ds = job_dataset(build, params.config, params.ensemble, path, path in params.ensemble_outputs)
    baseline_spec(onedof, reading).write(
        ds,
        path,
        f"Critical belt speed, reading {reading}",
        scene={"continuation": "natural parameter, increasing V_b"},
    )
    logging.info(
        "%s: critical speed %s mm/s; failures: %s", reading, float(ds.critical_belt_speed), ds.failures
    )
