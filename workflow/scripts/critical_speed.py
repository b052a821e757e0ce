"""Thin wiring: continuation over belt speed for one reading -> critical speed (Snakemake script)."""

import logging

import numpy as np
import xarray as xr

from stickslip.analysis.critical import continuation, critical_speed
from stickslip.analysis.divergence import BoundedSolver
from stickslip.io.netcdf import write_dataset
from stickslip.io.scenes import run_spec

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, format="%(asctime)s %(message)s")
config = snakemake.params.config
cfg = config["onedof"]["critical_speed"]
reading = snakemake.wildcards.reading
spec = run_spec(config, "fig02", reading, "exact")
speeds = np.geomspace(float(cfg["start"]), float(cfg["stop"]), int(cfg["num"]))
solver = BoundedSolver(spec.solver(), float(cfg["transient"]))
out, messages = continuation(
    spec.params, spec.variant, speeds, solver, float(cfg["t_end"]), float(cfg["transient"]), spec.output_dt
)
for m in messages:
    logging.info("failed: %s", m)
vc = critical_speed(speeds, out["stick_fraction"], out["solver_ok"])
stable = out["steady_sliding_stable"]
first_stable = float(speeds[np.argmax(stable == 1)]) if np.any(stable == 1) else float("inf")
units = {
    "stick_fraction": ("1", "fraction of steady-window samples in stick"),
    "stick_time": ("s", "mean stick duration"),
    "amplitude_peak_to_peak": ("mm", "peak-to-peak displacement"),
    "frequency_peaks": ("Hz", "frequency from peak spacing"),
    "solver_ok": ("1", "run finished and bounded (1)"),
    "steady_sliding_stable": ("1", "steady sliding linearly stable (1), neutral (0.5), unstable (0)"),
}
ds = xr.Dataset(
    {k: ("belt_velocity", out[k], {"units": u, "long_name": n}) for k, (u, n) in units.items()},
    coords={"belt_velocity": ("belt_velocity", speeds, {"units": "mm s-1", "long_name": "belt speed V_b"})},
)
ds["critical_belt_speed"] = (
    (),
    vc,
    {
        "units": "mm s-1",
        "long_name": "smallest V_b from which on no run sticks (0: never sticks; inf: none in range)",
    },
)
ds["steady_sliding_stable_from"] = (
    (),
    first_stable,
    {
        "units": "mm s-1",
        "long_name": "smallest swept V_b at which steady sliding is linearly stable (inf: none)",
    },
)
ds["has_critical_speed"] = (
    (),
    float(0 < vc < np.inf),
    {
        "units": "1",
        "long_name": "stick-slip present at low speed and gone above a finite speed (1) or not (0)",
    },
)
ds.attrs["failures"] = "; ".join(messages) or "none"
write_dataset(
    ds,
    snakemake.output[0],
    scene=spec.scene_attrs() | {"continuation": "natural parameter, increasing V_b"},
    interpretation=spec.interpretation(),
    method={"name": "exact", **spec.solver_settings},
    title=f"Critical belt speed, reading {reading}",
)
logging.info("critical speed %s mm/s", vc)
