"""Thin wiring: solve one scene x reading x method and write its dataset (Snakemake script).

A run whose oscillation grows without bound is recorded as a failure (solver_status = 1, with the reason),
never as a result (stickslip.analysis.divergence)."""

import logging

from stickslip.analysis.divergence import BoundedSolver
from stickslip.analysis.extra_metrics import extra_metrics
from stickslip.analysis.metrics import limit_cycle_metrics
from stickslip.io.netcdf import trajectory_dataset, write_dataset
from stickslip.io.scenes import run_spec

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, format="%(asctime)s %(message)s")
wc = snakemake.wildcards
spec = run_spec(snakemake.params.config, wc.scene, wc.reading, wc.method)
traj = BoundedSolver(spec.solver(), spec.transient).solve(spec.model, spec.t_end, spec.t_eval)
if not traj.ok:
    logging.warning("solver failed: %s (recorded in the dataset, metrics left out)", traj.stats.message)
metrics = limit_cycle_metrics(traj, spec.transient, spec.count_window)
ds = trajectory_dataset(traj, metrics)
if "stick_fraction" in ds:
    ds["slip_fraction"] = (
        (),
        1.0 - float(ds.stick_fraction),
        {"units": "1", "long_name": "fraction of steady-window samples in slip"},
    )
if traj.ok:
    for name, (value, units, long_name) in extra_metrics(
        traj.t, traj.x, traj.v, traj.belt_velocity, traj.phase, spec.model.friction, spec.params.normal_force
    ).items():
        ds[name] = ((), value, {"units": units, "long_name": long_name})
write_dataset(
    ds,
    snakemake.output[0],
    scene=spec.scene_attrs(),
    interpretation=spec.interpretation(),
    method={"name": spec.method, **spec.solver_settings, **traj.settings},
    title=f"{spec.figure} {spec.scene}: reading {spec.reading}, method {spec.method}",
)
logging.info(
    "%s %s %s: %s, %d segments/steps, cpu %.3f s",
    wc.scene,
    wc.reading,
    wc.method,
    traj.stats.status,
    traj.stats.steps,
    traj.stats.cpu_time,
)
