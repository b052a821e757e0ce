"""Thin wiring: render the methods notebook (presentation.notebook.render), its output in the log."""

import contextlib
from pathlib import Path

from stickslip.presentation.notebook import render

log = open(snakemake.log[0], "w")  # noqa: F821 (injected by Snakemake)
with log, contextlib.redirect_stdout(log), contextlib.redirect_stderr(log):
    render(Path(snakemake.input.notebook), Path(snakemake.output[0]))  # noqa: F821
