"""netCDF datasets with CF-style attributes and provenance, written atomically."""

from __future__ import annotations

import datetime as _dt
import errno
import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

from .._version import __version__
from ..analysis.metrics import Metric, cf_variable
from ..solvers.base import Trajectory
from .text_files import publish  # noqa: F401 (re-exported: the writers of other modules take it from here)

PAPER_REFERENCE = (
    "A. A. Yousif Mohammed, I. Abd Rahim: Investigate Stick-Slip Intervals with One Equation Of Motion "
    "And Analyse The Effect Of The Friction Noise"
)


def git_revision(cwd: str | os.PathLike | None = None) -> str:
    """Commit of the working tree (with '-dirty' when it has uncommitted changes), or 'unknown'."""
    cwd = cwd or Path(__file__).resolve().parent

    def git(*args, check=False) -> str:
        run = subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True, check=check, timeout=10)
        return run.stdout.strip()

    try:
        rev = git("rev-parse", "HEAD", check=True)
        return rev + ("-dirty" if git("status", "--porcelain", "--untracked-files=no") else "")
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


#: ``solver_status`` codes: a numerical failure computed nothing; a divergence is the model's answer.
SOLVER_STATUS = ("ok", "failed", "diverged")
#: CF flags of a per-sample or per-segment contact phase (``solvers.base``: -1, 0, 1).
PHASE_FLAGS = {
    "flag_values": np.array([-1, 0, 1], dtype=np.int8),
    "flag_meanings": "slip_backward stick slip_forward",
}


def trajectory_dataset(traj: Trajectory, metrics: dict[str, Metric] | None = None) -> xr.Dataset:
    """Time series of one run plus its metrics as scalar variables."""
    time = xr.Variable(
        "time", traj.t, {"units": "s", "long_name": "time", "standard_name": "time", "axis": "T"}
    )
    ds = xr.Dataset(
        {
            "displacement": cf_variable("time", traj.x, "mm", "mass displacement x"),
            "velocity": cf_variable("time", traj.v, "mm s-1", "mass velocity dx/dt"),
            "belt_velocity": cf_variable("time", traj.belt_velocity, "mm s-1", "belt velocity V_b"),
            "relative_velocity": cf_variable(
                "time", traj.relative_velocity, "mm s-1", "relative velocity v_r = dx/dt - V_b"
            ),
            "phase": (
                "time",
                traj.phase.astype(np.int8),
                {"long_name": "contact phase", "units": "1", **PHASE_FLAGS},
            ),
        },
        coords={"time": time},
    )
    if traj.segments is not None:
        seg = np.asarray(traj.segments, dtype=float).reshape(-1, 3)
        ds["segment_start"] = cf_variable("segment", seg[:, 0], "s", "segment start time")
        ds["segment_end"] = cf_variable("segment", seg[:, 1], "s", "segment end time")
        ds["segment_phase"] = cf_variable(
            "segment", seg[:, 2].astype(np.int8), "1", "segment contact phase", **PHASE_FLAGS
        )
    stats = traj.stats
    code, message = SOLVER_STATUS.index(stats.status), stats.message or "none"
    if code == 0 and not (np.all(np.isfinite(traj.x)) and np.all(np.isfinite(traj.v))):
        code, message = 1, "non-finite state (NaN or overflow) in the trajectory"
    ds["solver_status"] = (
        (),
        np.int8(code),
        {
            "long_name": "solver status",
            "units": "1",
            "flag_values": np.arange(len(SOLVER_STATUS), dtype=np.int8),
            "flag_meanings": " ".join(SOLVER_STATUS),
            "message": message,
        },
    )
    scalars = {}  # assigned at once: each single assignment re-aligns the whole dataset
    for name, units, long_name in (
        ("rhs_evaluations", "1", "right-hand-side evaluations"),
        ("steps", "1", "accepted steps or segments"),
        ("events", "1", "switching events handled"),
        ("cpu_time", "s", "process CPU time of the solve"),
    ):
        scalars[f"solver_{name}"] = cf_variable((), float(getattr(stats, name)), units, long_name)
    for name, metric in (metrics or {}).items():
        scalars[name] = cf_variable((), float(metric.value), metric.units, metric.long_name)
    return ds.assign(scalars)


def software_versions() -> dict:
    """Versions of the numerical stack and the BLAS in use: a result is only as reproducible as these."""
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for package in ("numpy", "scipy", "xarray", "netCDF4", "numba"):
        try:
            out[package] = version(package)
        except PackageNotFoundError:
            out[package] = "not installed"
    try:
        from threadpoolctl import threadpool_info

        blas = [i for i in threadpool_info() if i.get("user_api") == "blas"]
        described = [
            f"{i.get('internal_api')} {i.get('version')} ({i.get('architecture')}, "
            f"{i.get('num_threads')} threads)"
            for i in blas
        ]
        # sorted: the order threadpoolctl lists them in is the order numpy and scipy happened to load them
        out["blas"] = "; ".join(sorted(described)) or "none loaded"
    except ImportError:
        out["blas"] = "unknown (threadpoolctl not installed)"
    return out


def provenance_attrs(*, title: str, scene: dict, interpretation: str | dict, method: dict) -> dict:
    now = _dt.datetime.now(_dt.UTC).replace(microsecond=0).isoformat()
    attrs = {
        "Conventions": "CF-1.10",
        "title": title,
        "institution": "stickslip replication project",
        "source": f"stickslip {__version__} (git {git_revision()})",
        "history": f"{now} written by stickslip {__version__}",
        "references": PAPER_REFERENCE,
        "interpretation": interpretation
        if isinstance(interpretation, str)
        else json.dumps(interpretation, sort_keys=True),
    }
    attrs.update(flat_attrs("scene_", scene))
    attrs.update(flat_attrs("method_", method))
    attrs.update(flat_attrs("software_", software_versions()))
    return attrs


def _merged_attrs(existing: dict, provenance: dict) -> dict:
    """Provenance fills in; what the dataset already says wins (its title, Conventions, ...).

    ``history`` is the exception CF describes: an audit trail, so the writer's line is appended.
    """
    out = {**provenance, **existing}
    if existing.get("history"):
        out["history"] = f"{existing['history']}\n{provenance['history']}"
    return out


def cf_encoding(ds: xr.Dataset) -> dict:
    """Per-variable encoding: compressed float data; no ``_FillValue`` on coordinates (CF 2.5.1)."""
    encoding = {
        name: {"zlib": True, "complevel": 4}
        for name, var in ds.data_vars.items()
        if var.ndim > 0 and var.dtype.kind == "f"
    }
    for name in ds.coords:
        encoding.setdefault(str(name), {})["_FillValue"] = None
    return encoding


#: Attribute of the auxiliary coordinate that carries a dimension's text labels in a written file.
LABELS_OF = "labels_of_dimension"


def index_text_dimensions(ds: xr.Dataset) -> xr.Dataset:
    """Text dimension coordinates (scene names, claim ids, ...) as CF wants them: the dimension gets an
    integer index coordinate and the labels move to an auxiliary coordinate ``<dim>_label`` (CF 5: dimension
    coordinates are numeric and monotonic). ``read_dataset`` restores the labelled dimension."""
    for dim in [d for d in ds.dims if d in ds.coords and ds[d].dtype.kind in "OUS"]:
        labels = ds[dim]
        label_attrs = {**labels.attrs, LABELS_OF: str(dim)}
        label_attrs.setdefault("long_name", f"{str(dim).replace('_', ' ')} name")
        index_attrs = {"long_name": f"{str(dim).replace('_', ' ')} index", "units": "1"}
        ds = ds.assign_coords(
            {
                dim: (dim, np.arange(labels.size, dtype=np.int32), index_attrs),
                f"{dim}_label": (dim, np.asarray(labels.values, dtype=object), label_attrs),
            }
        )
    return ds


def label_text_dimensions(ds: xr.Dataset) -> xr.Dataset:
    """Inverse of ``index_text_dimensions``: the labels become the dimension coordinate again."""
    for name in [n for n in ds.coords if LABELS_OF in ds[n].attrs]:
        dim = ds[name].attrs[LABELS_OF]
        attrs = {k: v for k, v in ds[name].attrs.items() if k != LABELS_OF}
        labels = [str(v) for v in ds[name].values]
        ds = ds.drop_vars(name).assign_coords({dim: (dim, np.array(labels, dtype=object), attrs)})
    return ds


def cf_fill_in(ds: xr.Dataset) -> xr.Dataset:
    """Attributes CF asks for that a dataset may leave out, filled in without overwriting any.

    * a ``time`` coordinate gets ``standard_name: time`` and ``axis: T`` (CF 4.4, 5.1). Its units stay
      ``s``: it is elapsed simulated time, not a calendar date (see
      ``tests/end_to_end/test_cf_compliance.py``).
    * CPU-time variables get a ``comment`` saying they measure the machine (see ``is_machine_measurement``).
    * every variable gets a ``long_name`` (its name, spaced) if it has neither one nor a ``standard_name``.
    """
    if "time" in ds.coords:
        for key, value in (("standard_name", "time"), ("axis", "T"), ("long_name", "time")):
            ds["time"].attrs.setdefault(key, value)
    for name, var in ds.variables.items():
        if "long_name" not in var.attrs and "standard_name" not in var.attrs:
            var.attrs["long_name"] = str(name).replace("_", " ")
        if is_machine_measurement(str(name)):
            var.attrs.setdefault("comment", MACHINE_MEASUREMENT_COMMENT)
    return ds


#: Variables that measure the machine (CPU time and ratios of it), not the model: they differ between runs.
MACHINE_MEASUREMENT_COMMENT = "measured on the machine that ran the job: not reproducible bit for bit"


def is_machine_measurement(name: str) -> bool:
    """CPU times, and how many timing repeats they took: they measure the machine, not the model."""
    return "cpu_" in name or name.endswith("_cpu") or name in ("cpu", "repeats")


#: Free bytes below which a failed write is reported as a full disk (the netCDF library says only
#: "NetCDF: HDF error"): at least this much, or the dataset's in-memory size if larger, must be free.
MIN_FREE_BYTES = 1 << 20


class DiskFullError(OSError):
    """A dataset could not be written because its file system has no space left."""

    def __init__(self, path: Path, free: int, needed: int):
        super().__init__(
            errno.ENOSPC,
            f"no space left on device writing {path}: {free} bytes free in {path.parent}; the file needs an "
            f"estimated {needed} bytes (data, attributes and ~{VARIABLE_OVERHEAD_BYTES // 1024} KiB of "
            f"HDF5 structure per variable), and a write needs at least {MIN_FREE_BYTES} bytes (1 MiB) free "
            "(nothing was written under that name)",
        )


#: HDF5 structure per netCDF-4 variable (headers, chunk index, attribute heap), bounded from above by the
#: project's own datasets (a file of ~100 variables and ~10 KB of data takes ~400 KB).
VARIABLE_OVERHEAD_BYTES = 4096


def estimated_file_bytes(ds: xr.Dataset) -> int:
    """What writing ``ds`` takes on disk at most: its data, the text of its attributes and the HDF5
    structure of each variable (compression only makes the file smaller)."""
    attrs = sum(len(str(v)) + len(str(k)) for k, v in ds.attrs.items())
    attrs += sum(len(str(v)) + len(str(k)) for var in ds.variables.values() for k, v in var.attrs.items())
    return int(ds.nbytes) + attrs + VARIABLE_OVERHEAD_BYTES * (len(ds.variables) + 1)


def _disk_full(path: Path, needed: int, exc: BaseException | None = None) -> DiskFullError | None:
    """The error to raise when the folder of ``path`` lacks room for ``needed`` bytes (or ``exc`` says the
    disk is full), else None."""
    free = shutil.disk_usage(path.parent).free
    if free < max(needed, MIN_FREE_BYTES) or (isinstance(exc, OSError) and exc.errno == errno.ENOSPC):
        return DiskFullError(path, free, needed)
    return None


def write_dataset(
    ds: xr.Dataset,
    path: str | os.PathLike,
    *,
    scene: dict,
    interpretation: str | dict,
    method: dict,
    title: str | None = None,
) -> Path:
    """Attach provenance and write atomically: a temporary file in the target folder, then rename.

    Attributes the dataset already has are kept (``title`` given here is used only when the dataset has
    none). The temporary file is hidden (``.<name>.*.tmp``) and removed on any error, so a killed or failed
    job never leaves a readable partial file under the target name. A file system without room for it
    raises ``DiskFullError`` ('no space left on device'), checked before writing and again when the write
    fails (the netCDF library reports a full disk only as an HDF error).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    ds = ds.copy()
    prov = provenance_attrs(
        title=title or ds.attrs.get("title") or path.stem,
        scene=scene,
        interpretation=interpretation,
        method=method,
    )
    ds.attrs = _merged_attrs(ds.attrs, prov)
    ds = cf_fill_in(index_text_dimensions(ds))
    encoding = cf_encoding(ds)
    needed = estimated_file_bytes(ds)
    if full := _disk_full(path, needed):
        raise full
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as exc:
        if exc.errno == errno.ENOSPC:
            raise DiskFullError(path, shutil.disk_usage(path.parent).free, needed) from None
        raise
    os.close(fd)
    try:
        ds.to_netcdf(tmp, format="NETCDF4", engine="netcdf4", encoding=encoding)
        seal(tmp)
        publish(tmp, path)
    except BaseException as exc:
        Path(tmp).unlink(missing_ok=True)
        # measured with the partial file gone: what is free is what the write could have had
        if isinstance(exc, Exception) and (full := _disk_full(path, needed, exc)):
            raise full from exc
        raise
    return path


#: Global attribute holding the hash of everything else a dataset's file holds (``content_checksum``).
CHECKSUM_ATTR = "content_checksum"
#: The one command that rebuilds every dataset whose content no longer matches its checksum.
REPAIR_COMMAND = "make repair"


class CorruptDatasetError(OSError):
    """A dataset file cannot be read, or its content no longer matches the checksum it was written with."""


def _attr_bytes(attrs: dict) -> bytes:
    items = sorted((str(k), np.asarray(v).tolist()) for k, v in attrs.items() if k != CHECKSUM_ATTR)
    return repr(items).encode()


def content_checksum(raw: xr.Dataset) -> str:
    """sha256 of a dataset as stored (opened without decoding): every variable's name, dimensions, type,
    values and attributes, and the global attributes but the checksum itself."""
    import hashlib

    digest = hashlib.sha256(_attr_bytes(raw.attrs))
    for name in sorted(raw.variables, key=str):
        var = raw.variables[name]
        digest.update(f"\0{name}:{var.dims}:{var.dtype.str}:{var.shape}\0".encode())
        values = var.values
        digest.update(
            repr(values.tolist()).encode()
            if values.dtype.kind == "O"
            else np.ascontiguousarray(values).tobytes()
        )
        digest.update(_attr_bytes(var.attrs))
    return "sha256:" + digest.hexdigest()


def _open_raw(path) -> xr.Dataset:
    return xr.open_dataset(path, engine="netcdf4", decode_cf=False, mask_and_scale=False, decode_times=False)


def seal(path: str | os.PathLike) -> str:
    """Write the content checksum into a finished file (a global attribute; the data are not rewritten)."""
    import netCDF4

    with _open_raw(path) as raw:
        checksum = content_checksum(raw.load())
    with netCDF4.Dataset(path, "a") as nc:
        nc.setncattr(CHECKSUM_ATTR, checksum)
    return checksum


def read_dataset(path: str | os.PathLike) -> xr.Dataset:
    """Open a dataset fully into memory (closes the file), with a clear error if it is missing, unreadable
    (truncated) or no longer matches its content checksum (a bit flip, an edit by another program); text
    dimensions written as index + labels (``index_text_dimensions``) come back labelled."""
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"dataset {path} does not exist (has its rule run?)")
    try:
        with _open_raw(path) as raw:
            raw = raw.load()
    except Exception as exc:  # HDF5/netCDF errors of a damaged file come in several types
        raise CorruptDatasetError(
            f"dataset {path} cannot be read ({type(exc).__name__}: {exc}); it is damaged or truncated: "
            f"rebuild it with `{REPAIR_COMMAND}`"
        ) from None
    stored = raw.attrs.get(CHECKSUM_ATTR)
    if stored is None or content_checksum(raw) != stored:
        why = "has no content checksum" if stored is None else "no longer matches its content checksum"
        raise CorruptDatasetError(
            f"dataset {path} {why} (damaged, or changed since its rule wrote it): rebuild it with "
            f"`{REPAIR_COMMAND}`"
        )
    return label_text_dimensions(xr.decode_cf(raw))


def verify(paths) -> list[tuple[str, str]]:
    """(path, problem) for every dataset among ``paths`` that ``read_dataset`` refuses."""
    bad = []
    for path in paths:
        try:
            read_dataset(path)
        except (CorruptDatasetError, FileNotFoundError) as exc:
            bad.append((str(path), str(exc)))
    return bad


def main(argv=None) -> int:
    """``python -m stickslip.io.netcdf verify [FOLDER]``: print every damaged dataset under FOLDER (default
    results), one path per line, with its problem on stderr; exit 1 if there is one."""
    import sys

    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "verify" or len(argv) > 2:
        print("usage: python -m stickslip.io.netcdf verify [results]", file=sys.stderr)
        return 2
    folder = Path(argv[1] if len(argv) == 2 else "results")
    bad = verify(sorted(p for p in folder.rglob("*.nc") if not p.name.startswith(".")))
    for path, problem in bad:
        print(path)
        print(problem, file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
