"""Thin wiring: one paper figure for every reading, all its methods overlaid (Snakemake script)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.presentation.plots import onedof_figure  # noqa: E402

for reading, out in zip(snakemake.params.figure["readings"], snakemake.output):
    datasets = {m: read_dataset(p) for m, p in snakemake.params.datasets[reading].items()}
    fig = onedof_figure(datasets, snakemake.params.figure, reading=reading)
    fig.savefig(out, dpi=110)
    plt.close(fig)
