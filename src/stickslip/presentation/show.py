"""The text of ``stickslip show FILE.nc``: one dataset's title, provenance, scalar results with units, array
sizes and checksum state. The command prints it and the replication page shows it as each dataset's preview
(``page.write_dataset_previews``), so both always say the same thing."""

from __future__ import annotations

from pathlib import Path


def _fmt(value, unit: str = "") -> str:
    if value != value:
        return "n/a"
    # "1" is CF's unit of a pure number: "stick_count = 8 1" would read as two numbers
    return f"{value:.4g}" + (f" {unit}" if unit not in ("", "1") else "")


def summary_text(ds, checksum: str = "") -> str:
    """Title, provenance, scalar results with units, array variables and the checksum state."""
    attrs = ds.attrs
    lines = [str(attrs.get("title", "(untitled)"))]
    for key in ("source", "history", "interpretation", "method", "solver_message", "fe_reading"):
        if attrs.get(key):
            lines.append(f"  {key}: {str(attrs[key]).splitlines()[-1]}")
    method = {k[7:]: v for k, v in attrs.items() if k.startswith("method_")}
    scene = {k[6:]: v for k, v in attrs.items() if k.startswith("scene_")}
    if scene:
        lines.append("  scene: " + ", ".join(f"{k}={v}" for k, v in scene.items()))
    if method:
        lines.append("  method: " + ", ".join(f"{k}={v}" for k, v in method.items()))
    scalars = [n for n in ds.data_vars if ds[n].ndim == 0 and ds[n].dtype.kind in "fiu"]
    if scalars:
        lines.append("  results:")
        for name in scalars:
            lines.append(f"    {name} = {_fmt(float(ds[name]), ds[name].attrs.get('units', ''))}")
    series = [n for n in ds.data_vars if ds[n].ndim > 0]
    if series:
        dims = ", ".join(f"{d}={n}" for d, n in ds.sizes.items())
        lines.append(f"  {len(series)} array variables over {dims}")
    if checksum:
        lines.append(f"  checksum: {checksum}")
    return "\n".join(lines)


def show_state(path: Path) -> tuple[str, str]:
    """(text, state) of the dataset at ``path``: state ``ok`` (its checksum verified), ``mismatch`` (a
    dataset whose stored content no longer matches its checksum: summarised as stored, the checksum line
    saying MISMATCH and why) or ``unreadable`` (not a netCDF file at all, or truncated: the text says so)."""
    import xarray as xr

    from ..io.netcdf import CorruptDatasetError, read_dataset

    try:
        ds = read_dataset(path)
        return summary_text(ds, "ok (content matches content_checksum)"), "ok"
    except CorruptDatasetError as exc:
        state = f"MISMATCH: {exc}"
    except (OSError, ValueError) as exc:  # not a file netCDF can open at all
        return f"{path}: not a netCDF dataset ({type(exc).__name__}: {exc})", "unreadable"
    try:
        with xr.open_dataset(path) as opened:
            ds = opened.load()
    except Exception as exc:  # truncated or not netCDF at all: the state is all there is to say
        why = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        return f"{path}: not a readable netCDF dataset ({why})", "unreadable"
    return summary_text(ds, state), "mismatch"


def show_text(path: Path) -> str:
    """``summary_text`` of the dataset at ``path``, read with its checksum verified: a damaged file is still
    summarised (as stored), its checksum line saying MISMATCH and why."""
    text, state = show_state(path)
    if state == "unreadable":
        return f"{Path(path).name}: unreadable\n  checksum: {text}"
    return text
