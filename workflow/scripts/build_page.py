"""Thin wiring: the replication page, results/index.html, from the run's tables and images."""

from pathlib import Path

from stickslip.io.progress import log_to_file
from stickslip.presentation.page import PageBuilder, Source, build_page

log_to_file(snakemake.log[0], capture_output=True)

params = snakemake.params
builder = PageBuilder(
    workdir=Path.cwd(),
    claims=list(params.claims),
    sources=[Source(**s) for s in params.sources],
    notebooks=list(params.notebooks),
    inverse_figures=dict(params.inverse_figures),
    fe_default_reading=params.fe_default_reading,
    reading_descriptions=dict(params.reading_descriptions),
    friction_table=params.friction_table,
    workers=snakemake.threads,
    configuration=params.configuration,
)
build_page(Path(snakemake.output.html), builder)
