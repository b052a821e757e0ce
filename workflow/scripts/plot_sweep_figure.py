"""Thin wiring: Figs. 10-14, the paper's curves beside the dense sweep's metrics (Snakemake script)."""

import matplotlib

matplotlib.use("Agg")

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.plots import sweep_figure  # noqa: E402

fig = sweep_figure(
    read_dataset(snakemake.input.paper),
    read_dataset(snakemake.input.dense),
    snakemake.params.title,
    snakemake.wildcards.reading,
)
fig.savefig(snakemake.output[0], dpi=100)
