"""Thin wiring: FE readings overview, convergence and stability figures."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import xarray as xr  # noqa: E402

from stickslip.fe_plots import fe_convergence_figure, fe_readings_figure, fe_stability_figure  # noqa: E402

from fe_common import log_to  # noqa: E402

log_to(snakemake)  # noqa: F821
dss = {(Path(p).parent.name, Path(p).stem): xr.load_dataset(p) for p in snakemake.input.readings}  # noqa: F821
reported = {"max_horizontal_displacement": 0.00029, "mean_horizontal_displacement": -0.00015}
fig = fe_readings_figure(dss, snakemake.params.scenes, snakemake.params.readings, reported)  # noqa: F821
fig.savefig(snakemake.output.readings, dpi=100)  # noqa: F821
inp, out = snakemake.input, snakemake.output  # noqa: F821
fe_convergence_figure(xr.load_dataset(inp.convergence)).savefig(out.convergence, dpi=100)
fe_stability_figure(xr.load_dataset(inp.stability)).savefig(out.stability, dpi=100)
