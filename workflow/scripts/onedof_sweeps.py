"""Thin wiring: every parameter sweep (Figs. 10-14, belt speed) for one reading (Snakemake script).

Per sweep two datasets: the paper's values (metrics + time series, dims (<parameter>, time)) and a dense
version (>= 50 points, metrics only) - both through stickslip.analysis.sweep. Failed or diverging runs keep
NaN metrics and solver_ok = 0 (with the reason in failure_message)."""

import logging

import numpy as np
import xarray as xr

from stickslip.analysis.divergence import BoundedSolver
from stickslip.analysis.sweep import (
    chunk_dataset,
    chunk_points,
    grid_size,
    merge_chunks,
    run_points,
)
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import step_callback
from stickslip.io.scenes import sweep_spec
from stickslip.model.equations import BeltModel

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, format="%(asctime)s %(message)s")
reading = snakemake.wildcards.reading
config = snakemake.params.config


def sweep_dataset(spec, dense: bool) -> xr.Dataset:
    axis = spec.axis(dense)
    base = spec.base
    solver = BoundedSolver(base.solver(), base.transient)
    n = grid_size([axis])
    points = chunk_points([axis], n, 0)
    results = run_points(
        base.params,
        base.variant,
        points,
        solver,
        base.t_end,
        base.t_eval,
        base.transient,
        base.count_window,
        progress=step_callback(f"sweep {spec.figure} ({len(points)} runs)", sink=logging.info),
    )
    ds = merge_chunks([axis], [chunk_dataset([axis], n, 0, results)])
    for m in (
        "stick_fraction",
        "stick_time",
        "slip_time",
        "frequency_peaks",
        "amplitude_peak_to_peak",
        "amplitude_peak_to_zero",
    ):  # every run failed: keep the variables, all NaN
        if m not in ds:
            ds[m] = (
                spec.parameter,
                np.full(n, np.nan),
                {"units": "1", "long_name": f"{m} (no successful run)"},
            )
    ds["slip_fraction"] = (
        spec.parameter,
        1.0 - ds.stick_fraction.values,
        {"units": "1", "long_name": "fraction of steady-window samples in slip"},
    )
    messages = []
    if not dense:  # the paper's curves: keep each run's time series
        xs, vs = [], []
        for point in points:
            traj = solver.solve(
                BeltModel.build(base.params.with_(**point), base.variant), base.t_end, base.t_eval
            )
            messages.append(traj.stats.message or "none")
            ok = traj.ok
            xs.append(traj.x if ok else np.full_like(base.t_eval, np.nan))
            vs.append(traj.v if ok else np.full_like(base.t_eval, np.nan))
        ds = ds.assign_coords(time=("time", base.t_eval, {"units": "s", "long_name": "time"}))
        ds["displacement"] = (
            (spec.parameter, "time"),
            np.array(xs),
            {"units": "mm", "long_name": "mass displacement x"},
        )
        ds["velocity"] = (
            (spec.parameter, "time"),
            np.array(vs),
            {"units": "mm s-1", "long_name": "mass velocity"},
        )
        for m in (
            "frequency_peaks",
            "amplitude_peak_to_peak",
            "amplitude_peak_to_zero",
            "stick_time",
            "slip_time",
        ):
            for value in spec.values:  # scalars the claims table can name (e.g. frequency_peaks_at_0p9)
                ds[f"{m}_at_{value:g}".replace(".", "p")] = (
                    (),
                    float(ds[m].sel({spec.parameter: value})),
                    {
                        **ds[m].attrs,
                        "long_name": f"{ds[m].attrs['long_name']} at {spec.parameter} = {value:g}",
                    },
                )
    else:
        for point in points:
            traj = solver.solve(
                BeltModel.build(base.params.with_(**point), base.variant), base.t_end, base.t_eval
            )
            messages.append(traj.stats.message or "none")
    ds["failure_message"] = (
        spec.parameter,
        np.array(messages, dtype=object),
        {"long_name": "solver or divergence message of each run"},
    )
    ds.attrs.update(
        {
            "sweep_parameter": spec.parameter,
            "sweep_figure": spec.figure,
            "sweep_kind": "dense" if dense else "paper values",
            "failed_runs": int(np.sum(ds.solver_ok.values != 1)),
        }
    )
    return ds


for path in snakemake.output:
    name = path.split("/")[-2]
    dense = name.endswith("_dense")
    spec = sweep_spec(config, name[: -len("_dense")] if dense else name, reading)
    ds = sweep_dataset(spec, dense)
    write_dataset(
        ds,
        path,
        scene=spec.base.scene_attrs() | {"sweep": spec.name, "parameter": spec.parameter},
        interpretation=spec.base.interpretation(),
        method={"name": spec.base.method, **spec.base.solver_settings},
        title=f"{spec.figure} sweep over {spec.parameter} ({ds.attrs['sweep_kind']}), reading {reading}",
    )
    logging.info("%s: %d points, %d failed", path, ds.sizes[spec.parameter], ds.attrs["failed_runs"])
