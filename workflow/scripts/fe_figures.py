"""Thin wiring: every FE figure (one per paper figure 21-36, the paper scenes with the continuum overlaid,
readings, convergence, stability)."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402
from stickslip.io.progress import log_to_file  # noqa: E402
from stickslip.presentation.fe_paper_figures import paper_figure  # noqa: E402
from stickslip.presentation.fe_plots import (  # noqa: E402
    fe_convergence_figure,
    fe_readings_figure,
    fe_scene_figure,
    fe_stability_figure,
)

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
inp, out, par = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
# the inputs come in the rule's order (scenes; readings x scenes): paths are named, never parsed
beams = {scene: read_dataset(p) for scene, p in zip(par.scenes, inp.beam, strict=True)}
for (scene, beam), cont_path, png in zip(beams.items(), inp.continuum, out.scenes):
    cont = read_dataset(cont_path) if Path(cont_path).exists() else None  # only when run by hand
    title = (
        f"{scene} (FE reading {beam.attrs.get('fe_reading', '')}): beam 20 elements (blue) and "
        f"continuum 100x1 (black)"
    )
    reported = par.scene_reported.get(scene, {})
    fe_scene_figure(beam, cont, reported=reported, title=title).savefig(png, dpi=100)
    plt.close("all")
for number, png in zip(par.paper_figure_numbers, out.paper, strict=True):
    scenes = {s: beams[s] for s in par.paper_figures[number]}  # as config fe.paper_figures lists them
    reported = par.paper_reported.get(number, [])
    ratio = par.paper_normal_force_ratio
    paper_figure(number, scenes, reported, par.default_reading, several_times=ratio).savefig(png, dpi=100)
    plt.close("all")
keys = [(reading, scene) for reading in par.readings for scene in par.scenes]
# the default reading's datasets are the scenes' above: read once, drawn twice
dss = {
    key: beams[key[1]] if key[0] == par.default_reading else read_dataset(p)
    for key, p in zip(keys, inp.readings, strict=True)
}
fe_readings_figure(dss, par.scenes, par.readings, par.reported).savefig(out.readings, dpi=100)
fe_convergence_figure(read_dataset(inp.convergence)).savefig(out.convergence, dpi=100)
fe_stability_figure(read_dataset(inp.stability)).savefig(out.stability, dpi=100)
