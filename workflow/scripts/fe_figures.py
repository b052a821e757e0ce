"""Thin wiring: every FE figure (paper scenes with the continuum overlaid, readings, convergence,
stability)."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.io.progress import log_to_file  # noqa: E402
from stickslip.presentation.fe_plots import (  # noqa: E402
    fe_convergence_figure,
    fe_readings_figure,
    fe_scene_figure,
    fe_stability_figure,
)

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
inp, out, par = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
for beam_path, cont_path, png in zip(inp.beam, inp.continuum, out.scenes):
    beam, cont = read_dataset(beam_path), read_dataset(cont_path)
    title = (
        f"{Path(png).stem} (FE reading {beam.attrs.get('fe_reading', '')}): beam 20 elements (blue) and "
        f"continuum 100x1 (black), {float(beam.time[-1]):.3g} s"
    )
    reported = par.scene_reported.get(Path(png).stem, {})
    fe_scene_figure(beam, cont, reported=reported, title=title).savefig(png, dpi=100)
    plt.close("all")
dss = {(Path(p).parent.name, Path(p).stem): read_dataset(p) for p in inp.readings}
fe_readings_figure(dss, par.scenes, par.readings, par.reported).savefig(out.readings, dpi=100)
fe_convergence_figure(read_dataset(inp.convergence)).savefig(out.convergence, dpi=100)
fe_stability_figure(read_dataset(inp.stability)).savefig(out.stability, dpi=100)
