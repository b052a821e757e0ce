"""Which configuration a results folder belongs to, so that one configuration never writes into another's.

A build records, in ``<results>/.configuration``, the config overlays it was built with (the
``--configfile`` files beyond ``config/*.yaml``; none for the full build). A later build with other overlays
(the small CI configuration, an EXTENDING trial) is refused before any job runs: it would overwrite some of
the full build's results and leave the rest, and the page would mix the two. Such a configuration builds in
a folder of its own: ``make small`` (the small configuration in ``build/small/results``), or
``make small OVERLAY=<files> OVERLAY_DIR=<folder>`` for any other.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable
from pathlib import Path

OWNER_FILE = ".configuration"


class ForeignResultsError(RuntimeError):
    """The results folder holds the build of another configuration."""


def overlays(config_files: Iterable[str | Path], basedir: str | Path) -> list[str]:
    """The config files beyond the project's own ``config/*.yaml`` (paths relative to ``basedir`` where
    they lie inside it), in the order they were given."""
    base = (Path(basedir) / "config").resolve().parent  # the project itself, also from a linked folder
    own = {p.resolve() for p in (base / "config").glob("*.yaml")}
    out = []
    for f in config_files:
        path = Path(f).resolve()
        if path in own:
            continue
        out.append(str(path.relative_to(base)) if path.is_relative_to(base) else str(path))
    return out


def describe(overlay_files: list[str]) -> str:
    """The configuration in words, e.g. ``config/*.yaml + config/test/fe.yaml, ...``."""
    return "config/*.yaml" + "".join(f" + {f}" for f in overlay_files)


def recorded(results: str | Path) -> list[str] | None:
    """The overlays the build in ``results`` was made with; None if no build is recorded there."""
    path = Path(results) / OWNER_FILE
    try:
        return list(json.loads(path.read_text())["overlays"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def check(results: str | Path, overlay_files: list[str]) -> None:
    """Raise ForeignResultsError if ``results`` holds the build of another configuration."""
    before = recorded(results)
    if before is None or before == list(overlay_files):
        return
    raise ForeignResultsError(
        f"{results}/ holds the build of configuration {describe(before)}; this build is "
        f"{describe(overlay_files)} and would overwrite part of it. Build it in a folder of its own "
        "(`make small` for the small CI configuration, `make small OVERLAY=<files> OVERLAY_DIR=<folder>` "
        f"for another), or remove {results}/ first (`make clean`)."
    )


def record(results: str | Path, overlay_files: list[str]) -> None:
    """Write the configuration of the build about to run into ``results`` (atomically)."""
    folder = Path(results)
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / f"{OWNER_FILE}.tmp"
    tmp.write_text(json.dumps({"overlays": list(overlay_files)}, indent=1) + "\n")
    tmp.replace(folder / OWNER_FILE)


def claim(results: str | Path, overlay_files: list[str]) -> None:
    """Check, then record: for the build about to run (exits with the message if the folder is not ours)."""
    try:
        check(results, overlay_files)
    except ForeignResultsError as exc:
        sys.exit(f"Error: {exc}")
    record(results, overlay_files)
