"""Parameter sweeps: metrics of many runs on a grid, split into chunks that can run as separate jobs.

A sweep is a list of axes; the grid is their Cartesian product in C order (last axis fastest). A chunk is a
contiguous slice of the flattened grid, so any chunk size tiles the grid and chunks merge by concatenation.
An axis can carry linked parameters set proportionally (the paper's mass sweep raises N = 10 M with M).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ..model.equations import BeltModel
from ..model.laws import LawModel
from ..model.params import BeltParams, Count, ParameterError, checked_arguments
from .metrics import PAPER_COUNT_WINDOW, cf_variable, limit_cycle_metrics

if TYPE_CHECKING:  # the workflow builds sweep specs at parse time: xarray only where a dataset is made
    import xarray as xr


@dataclass(frozen=True)
class SweepAxis:
    name: str
    """Parameter of BeltParams that the axis sets."""
    values: tuple
    units: str = ""
    long_name: str = ""
    linked: dict = field(default_factory=dict)
    """Other parameters set to factor * value along this axis, e.g. {"normal_force": 10.0}."""

    def __post_init__(self):
        if len(self.values) == 0:
            raise ParameterError(f"sweep axis {self.name}: values is empty")
        if not all(isinstance(v, (int, float)) and math.isfinite(v) for v in self.values):
            raise ParameterError(f"sweep axis {self.name}: values must be finite numbers")

    def point(self, value: float) -> dict:
        """The parameter overrides of one value of this axis: the swept parameter and those linked to it."""
        return {self.name: float(value), **{k: float(f) * float(value) for k, f in self.linked.items()}}


def grid_size(axes: list[SweepAxis]) -> int:
    return int(np.prod([len(a.values) for a in axes]))


@checked_arguments(chunk_size=Count)
def chunk_count(axes: list[SweepAxis], chunk_size: int) -> int:
    return math.ceil(grid_size(axes) / chunk_size)


def chunk_points(axes: list[SweepAxis], chunk_size: int, chunk: int) -> list[dict]:
    """Parameter overrides of the grid points in one chunk (flattened C order)."""
    n = grid_size(axes)
    start, stop = chunk * chunk_size, min((chunk + 1) * chunk_size, n)
    if not 0 <= start < n:
        raise ParameterError(f"chunk: {chunk} out of range (0..{chunk_count(axes, chunk_size) - 1})")
    combos = itertools.islice(itertools.product(*(a.values for a in axes)), start, stop)
    return [
        {k: v for axis, value in zip(axes, combo) for k, v in axis.point(value).items()} for combo in combos
    ]


def run_points(
    base: BeltParams,
    variant: str,
    points: list[dict],
    solver,
    t_end: float,
    t_eval: np.ndarray,
    transient: float,
    count_window: float = PAPER_COUNT_WINDOW,
    progress: Callable[[int, int], None] | None = None,
    on_trajectory: Callable[[int, object], None] | None = None,
    law=None,
) -> dict[str, np.ndarray]:
    """Metric arrays (one entry per point); a failed run gives NaN metrics and solver_ok = 0.
    ``on_trajectory(i, traj)`` sees every run's trajectory (time series, messages) without solving twice.
    With a friction ``law`` (model/laws.py) each point is a ``LawModel`` (the law replaces the reading's
    friction; the solver must accept any law, i.e. the switch solver) instead of a ``BeltModel``."""
    rows = []
    for i, point in enumerate(points):
        params = base.with_(**point)
        model = BeltModel.build(params, variant) if law is None else LawModel(params, law)
        traj = solver.solve(model, t_end, t_eval)
        if on_trajectory is not None:
            on_trajectory(i, traj)
        rows.append(limit_cycle_metrics(traj, transient, count_window))
        if progress is not None:
            progress(i + 1, len(points))
    meta = {}  # each metric's first record (units, long name), in the order the runs name them
    for metrics in rows:
        for k, m in metrics.items():
            meta.setdefault(k, m)
    out = {k: np.array([row[k].value if k in row else np.nan for row in rows], dtype=float) for k in meta}
    out["_meta"] = meta
    return out


def chunk_dataset(axes: list[SweepAxis], chunk_size: int, chunk: int, results: dict) -> xr.Dataset:
    """One chunk as a dataset over the flattened grid index ``point``."""
    import xarray as xr

    n = grid_size(axes)
    start = chunk * chunk_size
    count = len(next(v for k, v in results.items() if k != "_meta"))
    index = np.arange(start, start + count)
    ds = xr.Dataset(coords={"point": ("point", index, {"long_name": "flattened grid index", "units": "1"})})
    ds = ds.assign(
        {
            name: cf_variable("point", results[name], metric.units, metric.long_name)
            for name, metric in results["_meta"].items()
        }
    )
    ds.attrs["grid_size"] = n
    return ds


def merge_chunks(axes: list[SweepAxis], chunks: list[xr.Dataset]) -> xr.Dataset:
    """Concatenate chunk datasets and unflatten the grid into one dimension per axis."""
    import xarray as xr

    flat = xr.concat(sorted(chunks, key=lambda d: int(d.point[0])), dim="point")
    n = grid_size(axes)
    if flat.sizes["point"] != n or not np.array_equal(flat.point.values, np.arange(n)):
        raise ValueError(f"chunks cover {flat.sizes['point']} of {n} grid points or overlap")
    shape = [len(a.values) for a in axes]
    dims = [a.name for a in axes]
    out = xr.Dataset(
        coords={
            a.name: cf_variable(
                a.name, np.asarray(a.values, dtype=float), a.units or "1", a.long_name or a.name
            )
            for a in axes
        }
    )
    for name, var in flat.data_vars.items():
        out[name] = (dims, var.values.reshape(shape), dict(var.attrs))
    for axis in axes:
        for other, factor in axis.linked.items():
            values = float(factor) * np.asarray(axis.values, dtype=float)
            out[other] = cf_variable(
                axis.name, values, "1", f"{other} linked to {axis.name} (factor {factor:g})"
            )
    return out


def align_chunks(chunks: list[xr.Dataset]) -> list[xr.Dataset]:
    """Give every chunk the same variables: a chunk whose runs all failed carries only ``solver_ok``, so
    metrics missing from a chunk are added as NaN (with the attributes another chunk gives them)."""
    attrs = {}
    for ds in chunks:
        for name, var in ds.data_vars.items():
            attrs.setdefault(name, dict(var.attrs))
    out = []
    for ds in chunks:
        ds = ds.copy()
        for name, var_attrs in attrs.items():
            if name not in ds:
                ds[name] = ("point", np.full(ds.sizes["point"], np.nan), var_attrs)
        out.append(ds[list(attrs)])
    return out
