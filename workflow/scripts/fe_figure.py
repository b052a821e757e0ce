"""Thin wiring: one paper scene (default FE reading) with the continuum overlaid -> PNG."""

import matplotlib

matplotlib.use("Agg")
import xarray as xr  # noqa: E402

from stickslip.fe_plots import fe_scene_figure  # noqa: E402

from fe_common import log_to  # noqa: E402

log_to(snakemake)  # noqa: F821
beam = xr.load_dataset(snakemake.input.beam)  # noqa: F821
cont = xr.load_dataset(snakemake.input.continuum)  # noqa: F821
title = f"{snakemake.wildcards.scene} ({beam.attrs.get('fe_reading', '')}): beam {float(beam.time[-1]):g} s, continuum 100x1 {float(cont.time[-1]):g} s"  # noqa: E501, F821
fe_scene_figure(beam, cont, title=title).savefig(snakemake.output[0], dpi=100)  # noqa: F821
