"""Thin wiring: every comparison notebook of the config in one job, ``threads`` kernels at a time
(presentation.notebook.render_all); exits non-zero naming each notebook that failed (its log has why)."""

import sys

from stickslip.presentation.notebook import render_all

params = snakemake.params.nb_params  # noqa: F821 - {name: PARAMS}, in the order of the outputs
jobs = [
    (source, target, params[name], log)
    for name, source, target, log in zip(
        params,
        snakemake.input.notebooks,  # noqa: F821
        snakemake.output,  # noqa: F821
        snakemake.log,  # noqa: F821
        strict=True,
    )
]
failed = render_all(jobs, workers=snakemake.threads)  # noqa: F821
if failed:
    sys.exit(f"notebooks failed: {', '.join(failed)} (tracebacks in results/logs/render_notebooks/)")
