"""Convergence study or stability map (params.kind) -> netCDF."""

import stickslip.fe.pipeline as fe_pipeline
from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, convergence_dataset, stability_dataset

from fe_common import log_to, track_calls, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
kind = snakemake.params.kind  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
if kind == "convergence":  # one transient per mesh and time step
    runs = len(cfg[kind]["n_elements"]) * len(cfg[kind].get("safety_factors", [0]))
    progress = track_calls(fe_pipeline, "run_scene", runs, label=kind, every=5.0)
else:  # the eigenvalue map is cheap; the cross-check transients are what takes time
    progress = track_calls(
        fe_pipeline, "transient_growth", len(cfg[kind].get("crosscheck", [])), label=kind, every=5.0
    )
ds = (convergence_dataset if kind == "convergence" else stability_dataset)(cfg, friction)
progress.finish()
print(ds)
write_dataset(
    ds,
    snakemake.output[0],  # noqa: F821
    scene=dict(cfg[kind]),
    interpretation=INTERPRETATION,
    method={"study": kind},
)
