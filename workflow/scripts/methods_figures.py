"""Snakemake script: work-precision charts (one per scene) and the failure map figure."""

import os

import matplotlib

matplotlib.use("Agg")


from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.presentation.methods_plots import failure_map_figure, work_precision_figure  # noqa: E402

sm = snakemake  # noqa: F821
for nc, png in zip(sm.input.work_precision, sm.output.work_precision):
    fig = work_precision_figure(read_dataset(nc), os.path.basename(nc).replace("_work_precision.nc", ""))
    os.makedirs(os.path.dirname(png), exist_ok=True)
    fig.savefig(png, dpi=110, bbox_inches="tight")  # long method labels: nothing clipped
failure_map_figure(read_dataset(sm.input.failure_map)).savefig(
    sm.output.failure_map, dpi=110, bbox_inches="tight"
)
