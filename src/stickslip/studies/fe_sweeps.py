"""Sweeps of one FE scene parameter (``fe.sweeps``): one run per value, the scalar metrics along the sweep,
and the same runs at half the time step (the step-halving check)."""

from __future__ import annotations

import copy
import json
from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.params import FrictionTable
from ..fe.quantities import INTERPRETATION, cf_attrs, metric_attrs
from ..schema.fe import FeJob, FeSweep
from .fe_config import as_mapping, halved_step
from .fe_scene import run_scene


def sweep_member(base: Mapping, sweep: FeSweep, value) -> dict:
    """The base scene with the swept ``section.key`` set to ``value`` (and the sweep's own t_end)."""
    section, key = sweep.parameter.split(".")
    mp = copy.deepcopy(base)
    mp.setdefault(section, {})[key] = value
    if sweep.t_end is not None:
        mp.setdefault("solver", {})["t_end"] = sweep.t_end
    return mp


def _sweep_rows(job: FeJob, sweep_name: str, friction: FrictionTable, half_step: bool = False):
    sw = job.sweeps[sweep_name]
    base = as_mapping(job.scenes[sw.base])
    rows = []
    for val in sw.values:
        mp = sweep_member(base, sw, val)
        _, m, _ = run_scene(halved_step(mp) if half_step else mp, friction)
        rows.append(m)
    return base, rows


def _scalar_columns(rows: list[dict]) -> dict:
    """Each scalar metric of the runs as an array along the sweep."""
    return {k: np.array([r[k] for r in rows], float) for k in rows[0] if np.isscalar(rows[0][k])}


def sweep_half_step(job: FeJob, sweep_name: str, friction: FrictionTable) -> dict:
    """Every sweep member's scalar metrics at half its time step, as arrays along the sweep."""
    _, rows = _sweep_rows(job, sweep_name, friction, half_step=True)
    return _scalar_columns(rows)


def sweep_dataset(job: FeJob, sweep_name: str, friction: FrictionTable) -> xr.Dataset:
    sw = job.sweeps[sweep_name]
    base, rows = _sweep_rows(job, sweep_name, friction)
    coord = sw.coord
    ds = xr.Dataset(
        {k: (coord, v, metric_attrs(k)) for k, v in _scalar_columns(rows).items()},
        coords={coord: cf_variable(coord, np.array(sw.values, float), sw.units, sw.long_name or coord)},
    )
    ds.attrs.update(
        cf_attrs(
            f"Beam-on-disc sweep {sweep_name}",
            model_interpretation=INTERPRETATION,
            base_scene=sw.base,
            parameters=json.dumps(base),
            method="explicit central difference, one run per sweep value",
        )
    )
    return ds
