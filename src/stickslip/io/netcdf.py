"""netCDF datasets with CF-style attributes and provenance, written atomically."""

from __future__ import annotations

import datetime as _dt
import json
import os
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

from .. import __version__
from ..analysis.metrics import Metric
from ..solvers.base import Trajectory

PAPER_REFERENCE = (
    "A. A. Yousif Mohammed, I. Abd Rahim: Investigate Stick-Slip Intervals with One Equation Of Motion "
    "And Analyse The Effect Of The Friction Noise"
)


def git_revision(cwd: str | os.PathLike | None = None) -> str:
    """Commit of the working tree (with '-dirty' when it has uncommitted changes), or 'unknown'."""
    cwd = cwd or Path(__file__).resolve().parent
    try:
        rev = subprocess.run(["git", "rev-parse", "HEAD"], cwd=cwd, capture_output=True, text=True,
                             check=True, timeout=10).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=cwd,
                               capture_output=True, text=True, timeout=10).stdout.strip()
        return rev + ("-dirty" if dirty else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def _attr_value(value):
    """netCDF attributes hold strings and numbers only: encode the rest as JSON."""
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    if isinstance(value, (int, float, str, np.integer, np.floating)):
        return value
    if value is None:
        return "none"
    return json.dumps(value, sort_keys=True, default=str)


def flat_attrs(prefix: str, mapping: dict) -> dict:
    return {f"{prefix}{key}": _attr_value(val) for key, val in sorted(mapping.items())}


def trajectory_dataset(traj: Trajectory, metrics: dict[str, Metric] | None = None) -> xr.Dataset:
    """Time series of one run plus its metrics as scalar variables."""
    time = xr.Variable("time", traj.t, {"units": "s", "long_name": "time", "standard_name": "time",
                                       "axis": "T"})
    ds = xr.Dataset(
        {
            "displacement": ("time", traj.x, {"units": "mm", "long_name": "mass displacement x"}),
            "velocity": ("time", traj.v, {"units": "mm s-1", "long_name": "mass velocity dx/dt"}),
            "belt_velocity": ("time", traj.belt_velocity, {"units": "mm s-1", "long_name": "belt velocity V_b"}),
            "relative_velocity": ("time", traj.relative_velocity,
                                  {"units": "mm s-1", "long_name": "relative velocity v_r = dx/dt - V_b"}),
            "phase": ("time", traj.phase.astype(np.int8), {
                "long_name": "contact phase", "units": "1", "flag_values": np.array([-1, 0, 1], dtype=np.int8),
                "flag_meanings": "slip_backward stick slip_forward"}),
        },
        coords={"time": time},
    )
    if traj.segments is not None:
        seg = np.asarray(traj.segments, dtype=float).reshape(-1, 3)
        ds["segment_start"] = ("segment", seg[:, 0], {"units": "s", "long_name": "segment start time"})
        ds["segment_end"] = ("segment", seg[:, 1], {"units": "s", "long_name": "segment end time"})
        ds["segment_phase"] = ("segment", seg[:, 2].astype(np.int8), {
            "units": "1", "long_name": "segment contact phase",
            "flag_values": np.array([-1, 0, 1], dtype=np.int8), "flag_meanings": "slip_backward stick slip_forward"})
    stats = traj.stats
    ds["solver_status"] = ((), np.int8(0 if stats.status == "ok" else 1), {
        "long_name": "solver status", "units": "1", "flag_values": np.array([0, 1], dtype=np.int8),
        "flag_meanings": "ok failed", "message": stats.message or "none"})
    for name, units, long_name in (
        ("rhs_evaluations", "1", "right-hand-side evaluations"), ("steps", "1", "accepted steps or segments"),
        ("events", "1", "switching events handled"), ("cpu_time", "s", "process CPU time of the solve"),
    ):
        ds[f"solver_{name}"] = ((), float(getattr(stats, name)), {"units": units, "long_name": long_name})
    for name, metric in (metrics or {}).items():
        ds[name] = ((), float(metric.value), {"units": metric.units, "long_name": metric.long_name})
    return ds


def provenance_attrs(*, title: str, scene: dict, interpretation: str | dict, method: dict) -> dict:
    now = _dt.datetime.now(_dt.timezone.utc).replace(microsecond=0).isoformat()
    attrs = {
        "Conventions": "CF-1.10",
        "title": title,
        "institution": "stickslip replication project",
        "source": f"stickslip {__version__} (git {git_revision()})",
        "history": f"{now} written by stickslip {__version__}",
        "references": PAPER_REFERENCE,
        "interpretation": interpretation if isinstance(interpretation, str) else json.dumps(interpretation,
                                                                                             sort_keys=True),
    }
    attrs.update(flat_attrs("scene_", scene))
    attrs.update(flat_attrs("method_", method))
    return attrs


def write_dataset(ds: xr.Dataset, path: str | os.PathLike, *, scene: dict, interpretation: str | dict,
                  method: dict, title: str | None = None) -> Path:
    """Attach provenance and write atomically: a temporary file in the target folder, then rename."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    ds = ds.copy()
    ds.attrs.update(provenance_attrs(title=title or ds.attrs.get("title", path.stem), scene=scene,
                                     interpretation=interpretation, method=method))
    encoding = {name: {"zlib": True, "complevel": 4} for name, var in ds.data_vars.items() if var.ndim > 0
                and var.dtype.kind == "f"}
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        ds.to_netcdf(tmp, format="NETCDF4", engine="netcdf4", encoding=encoding)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def read_dataset(path: str | os.PathLike) -> xr.Dataset:
    """Open a dataset fully into memory (closes the file), with a clear error if it is missing."""
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"dataset {path} does not exist (has its rule run?)")
    with xr.open_dataset(path) as ds:
        return ds.load()
