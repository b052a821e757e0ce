"""Thin helpers shared by the fe_* workflow scripts (wiring only, no science)."""

from __future__ import annotations

import logging
import sys

from stickslip.io.netcdf import write_dataset as shared_write_dataset


def write_dataset(ds, path, *, scene: dict, interpretation: str, method: dict) -> None:
    """The shared provenance writer (atomic, CF attributes)."""
    shared_write_dataset(ds, path, scene=scene, interpretation=interpretation, method=method)


def log_to(snakemake) -> None:
    """Send stdout/stderr and the progress log of a script run to the rule's log file (line-buffered)."""
    if snakemake.log:
        f = open(snakemake.log[0], "w", buffering=1)
        sys.stdout = sys.stderr = f
        logging.basicConfig(stream=f, level=logging.INFO, format="%(asctime)s %(message)s", force=True)
