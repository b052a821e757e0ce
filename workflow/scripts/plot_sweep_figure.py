"""Thin wiring: Figs. 10-14, the paper's curves beside the dense sweep's metrics, one PNG per reading."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.presentation.plots import sweep_figure  # noqa: E402

for reading, out in zip(snakemake.params.readings, snakemake.output):
    paper, dense = (read_dataset(p) for p in snakemake.params.datasets[reading])
    fig = sweep_figure(paper, dense, snakemake.params.title, reading)
    fig.savefig(out, dpi=100)
    plt.close(fig)
