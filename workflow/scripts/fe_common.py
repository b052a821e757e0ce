"""Thin helpers shared by the fe_* workflow scripts (wiring only, no science)."""

from __future__ import annotations

import logging
import sys

from stickslip.io.netcdf import write_dataset as shared_write_dataset


def write_dataset(ds, path, *, scene: dict, interpretation: str, method: dict) -> None:
    """The shared provenance writer (atomic, CF attributes)."""
    shared_write_dataset(ds, path, scene=scene, interpretation=interpretation, method=method)


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
