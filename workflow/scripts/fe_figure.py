"""Thin wiring: one beam-on-disc scene dataset -> PNG (whole run and a zoom on the last periods)."""

import matplotlib

matplotlib.use("Agg")
import xarray as xr  # noqa: E402

from stickslip.plots import fe_scene_figure  # noqa: E402

from fe_common import log_to  # noqa: E402

log_to(snakemake)  # noqa: F821
ds = xr.load_dataset(snakemake.input[0])  # noqa: F821
fe_scene_figure(ds).savefig(snakemake.output[0], dpi=110)  # noqa: F821
