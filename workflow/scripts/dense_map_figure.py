"""Thin wiring: one colour map per metric of a dense map; failed runs (solver_ok = 0 or NaN) are masked."""

import matplotlib

matplotlib.use("Agg")

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.io.progress import log_to_file  # noqa: E402
from stickslip.presentation.plots import dense_map_figure  # noqa: E402

log_to_file(snakemake.log[0])  # noqa: F821
ds = read_dataset(snakemake.input[0])  # noqa: F821
fig = dense_map_figure(ds, snakemake.params.plot, snakemake.params.title)  # noqa: F821
fig.savefig(snakemake.output[0], dpi=120)  # noqa: F821
