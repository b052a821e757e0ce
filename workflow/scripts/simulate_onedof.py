"""Thin wiring: solve one scene x reading x method and write its dataset (Snakemake script)."""

import logging

from stickslip.analysis.metrics import limit_cycle_metrics
from stickslip.io.netcdf import trajectory_dataset, write_dataset
from stickslip.io.scenes import run_spec

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, format="%(asctime)s %(message)s")
wc = snakemake.wildcards
spec = run_spec(snakemake.params.config, wc.scene, wc.reading, wc.method)
traj = spec.solver().solve(spec.model, spec.t_end, spec.t_eval)
if not traj.ok:
    logging.warning("solver failed: %s (recorded in the dataset, metrics left out)", traj.stats.message)
metrics = limit_cycle_metrics(traj, spec.transient, spec.count_window)
ds = trajectory_dataset(traj, metrics)
write_dataset(
    ds, snakemake.output[0], scene=spec.scene_attrs(), interpretation=spec.interpretation(),
    method={"name": spec.method, **spec.solver_settings, **traj.settings},
    title=f"{spec.figure} {spec.scene}: reading {spec.reading}, method {spec.method}",
)
logging.info("%s %s %s: %s, %d segments/steps, cpu %.3f s", wc.scene, wc.reading, wc.method, traj.stats.status,
             traj.stats.steps, traj.stats.cpu_time)
