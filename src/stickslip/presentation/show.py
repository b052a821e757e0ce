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


def show_text(path: Path) -> str:
    """``summary_text`` of the dataset at ``path``, read with its checksum verified: a damaged file is still
    summarised (as stored), its checksum line saying MISMATCH and why."""
    from ..io.netcdf import CorruptDatasetError, read_dataset

    try:
        ds = read_dataset(path)
        state = "ok (content matches content_checksum)"
    except CorruptDatasetError as exc:
        import xarray as xr

        state = f"MISMATCH: {exc}"
        try:
            with xr.open_dataset(path) as opened:
                ds = opened.load()
        except Exception:  # truncated or not netCDF at all: the state is all there is to say
            return f"{Path(path).name}: unreadable\n  checksum: {state}"
    return summary_text(ds, state)
