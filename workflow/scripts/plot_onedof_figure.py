"""Thin wiring: one paper figure for one reading, all its methods overlaid (Snakemake script)."""

import matplotlib

matplotlib.use("Agg")

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.plots import onedof_figure  # noqa: E402

datasets = {m: read_dataset(p) for m, p in zip(snakemake.params.methods, snakemake.input)}
fig = onedof_figure(datasets, snakemake.params.figure, reading=snakemake.wildcards.reading)
fig.savefig(snakemake.output[0], dpi=110)
