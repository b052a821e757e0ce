"""The text of ``stickslip show FILE.nc``: one dataset's title, provenance, scalar results with units, array
sizes and checksum state. The command prints it and the replication page shows it as each dataset's preview
(``PageBuilder.write_text_pages``), so both always say the same thing."""

from __future__ import annotations

from pathlib import Path


def _fmt(value, unit: str = "") -> str:
    if value != value:
        return "n/a"
    # "1" is CF's unit of a pure number: "stick_count = 8 1" would read as two numbers
    return f"{value:.4g}" + (f" {unit}" if unit not in ("", "1") else "")


def _outcome(ds) -> str:
    """The run's outcome in words (its ``outcome`` code named by the flag meanings)."""
    meanings = str(ds["outcome"].attrs.get("flag_meanings", "")).split()
    code = int(ds["outcome"].values)
    return (meanings[code] if 0 <= code < len(meanings) else str(code)).replace("_", " ")


def _why_undefined(ds, name: str) -> str:
    """Why a scalar is NaN, in words: withheld by the step-halving check (the values at dt and dt/2 differ),
    or not defined by the run (its outcome: a run that diverges has no steady cycle to measure)."""
    halving = str(ds[name].attrs.get("step_halving", ""))
    if halving.startswith("not converged"):
        return "withheld: the values at dt and dt/2 differ; " + halving.split(": ", 1)[-1]
    if halving:
        return halving.split(";")[0]
    if "outcome" in ds and "flag_meanings" in ds["outcome"].attrs:
        return f"not defined by this run, whose outcome is {_outcome(ds)}"
    return "not defined by this run"


def summary_text(ds, checksum: str = "") -> str:
    """Title, provenance, scalar results with units, array variables and the checksum state."""
    attrs = ds.attrs
    lines = [str(attrs.get("title", "(untitled)"))]
    for key in ("source", "history", "interpretation", "method", "solver_message", "fe_reading"):
        if attrs.get(key):
            lines.append(f"  {key}: {str(attrs[key]).splitlines()[-1]}")
    for prefix in ("scene", "method"):  # the scene_* and method_* attributes, one line each
        found = {k.removeprefix(f"{prefix}_"): v for k, v in attrs.items() if k.startswith(f"{prefix}_")}
        if found:
            lines.append(f"  {prefix}: " + ", ".join(f"{k}={v}" for k, v in found.items()))
    if "outcome" in ds and "mechanism" in ds["outcome"].attrs:  # the run's answer, before its numbers
        lines.insert(1, f"  outcome: {_outcome(ds)}: {ds['outcome'].attrs['mechanism']}")
    scalars = [n for n in ds.data_vars if ds[n].ndim == 0 and ds[n].dtype.kind in "fiu"]
    undefined: dict[str, list[str]] = {}
    if scalars:
        lines.append("  results:")
        for name in scalars:
            value = float(ds[name])
            if value != value:  # grouped below by why, not one 'n/a' line each
                undefined.setdefault(_why_undefined(ds, name), []).append(name)
                continue
            lines.append(f"    {name} = {_fmt(value, ds[name].attrs.get('units', ''))}")
    for why, names in undefined.items():
        lines.append(f"  n/a ({why}): {', '.join(names)}")
    series = [n for n in ds.data_vars if ds[n].ndim > 0]
    if series:
        dims = ", ".join(f"{d}={n}" for d, n in ds.sizes.items())
        lines.append(f"  {len(series)} array variables over {dims}")
    if checksum:
        lines.append(f"  checksum: {checksum}")
    return "\n".join(lines)


#: The first bytes of a netCDF file: classic (CDF) or netCDF-4 (HDF5).
NETCDF_MAGIC = (b"CDF\x01", b"CDF\x02", b"CDF\x05", b"\x89HDF\r\n\x1a\n")


def _looks_like_netcdf(path: Path) -> bool:
    try:
        with open(path, "rb") as fh:
            head = fh.read(8)
    except OSError:
        return False
    return any(head.startswith(magic) for magic in NETCDF_MAGIC)


def show_state(path: Path) -> tuple[str, str]:
    """(text, state) of the file at ``path``: ``ok`` (a dataset, its checksum verified), ``mismatch`` (a
    netCDF file whose content does not match its checksum, or truncated: summarised as far as it can be read,
    the checksum line saying MISMATCH and why) or ``unreadable`` (not a netCDF file at all: the text says so,
    and advises no rebuild)."""
    import xarray as xr

    from ..io.netcdf import CorruptDatasetError, read_dataset

    path = Path(path)
    if not _looks_like_netcdf(path):
        return f"{path}: not a netCDF dataset (its first bytes are no netCDF or HDF5 signature)", "unreadable"
    try:
        ds = read_dataset(path)
        return summary_text(ds, "ok (content matches content_checksum)"), "ok"
    except CorruptDatasetError as exc:
        state = f"MISMATCH: {exc}"
    try:
        with xr.open_dataset(path) as opened:
            ds = opened.load()
    except Exception:  # truncated: the state is all there is to say
        return f"{path.name}: unreadable\n  checksum: {state}", "mismatch"
    return summary_text(ds, state), "mismatch"


def show_text(path: Path) -> str:
    """``summary_text`` of the dataset at ``path``, read with its checksum verified: a damaged file is still
    summarised (as stored), its checksum line saying MISMATCH and why."""
    text, state = show_state(path)
    return f"{Path(path).name}: unreadable\n  checksum: {text}" if state == "unreadable" else text
