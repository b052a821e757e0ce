"""Thin wiring: one paper figure for every reading, all its methods overlaid (Snakemake script)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.presentation.plots import onedof_figure  # noqa: E402
from stickslip.schema import Figure  # noqa: E402

figure = Figure.model_validate(snakemake.params.figure)  # noqa: F821
for reading, out in zip(figure.readings, snakemake.output):  # noqa: F821
    datasets = {m: read_dataset(p) for m, p in snakemake.params.datasets[reading].items()}  # noqa: F821
    fig = onedof_figure(datasets, figure, reading=reading)
    fig.savefig(out, dpi=110)
    plt.close(fig)
