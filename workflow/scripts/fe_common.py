"""Thin helpers shared by the fe_* workflow scripts (wiring only, no science)."""

from __future__ import annotations

import logging
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import stickslip


def write_dataset(ds, path, *, scene: dict, interpretation: str, method: dict) -> None:
    """Use the shared provenance writer when present; otherwise a minimal atomic fallback."""
    try:
        from stickslip.io.netcdf import write_dataset as shared
    except ImportError:
        shared = None
    if shared is not None:
        shared(ds, path, scene=scene, interpretation=interpretation, method=method)
        return
    import json

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        rev = subprocess.run(
            ["git", "rev-parse", "HEAD"], capture_output=True, text=True, check=False
        ).stdout.strip()
    except OSError:
        rev = "unknown"
    ds = ds.copy()
    ds.attrs.setdefault("Conventions", "CF-1.10")
    ds.attrs["source"] = f"stickslip {stickslip.__version__}, git {rev or 'unknown'}"
    ds.attrs["history"] = f"written by {' '.join(sys.argv[:1])} (fe_common fallback writer)"
    ds.attrs["scene_parameters"] = json.dumps(scene, default=str)
    ds.attrs["model_interpretation"] = interpretation
    ds.attrs["method_settings"] = json.dumps(method, default=str)
    fd, tmp = tempfile.mkstemp(suffix=".nc.tmp", dir=path.parent)
    os.close(fd)
    try:
        ds.to_netcdf(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def track_calls(module, name: str, total: int, label: str, every: float = 10.0):
    """Wrap ``module.name`` so that every call advances a ``stickslip.io.progress.Progress`` of ``total``.

    The FE library functions loop internally (one ``run_scene`` per sweep value or mesh); counting those
    calls from the script gives ``done/total, elapsed, ETA`` lines in the rule's log without touching the
    science code. Lines are printed (the log file is stdout after :func:`log_to`).
    """
    from stickslip.io.progress import Progress

    progress = Progress(total, label=label, every=every, sink=lambda line: print(line, flush=True))
    inner = getattr(module, name)

    def counted(*args, **kwargs):
        out = inner(*args, **kwargs)
        progress.advance()
        return out

    setattr(module, name, counted)
    print(f"{label}: {total} runs to do", flush=True)
    return progress


def log_to(snakemake) -> None:
    """Send stdout/stderr and the progress log of a script run to the rule's log file (line-buffered)."""
    if snakemake.log:
        f = open(snakemake.log[0], "w", buffering=1)
        sys.stdout = sys.stderr = f
        logging.basicConfig(stream=f, level=logging.INFO, format="%(asctime)s %(message)s", force=True)
