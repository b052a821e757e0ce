"""`make figures` and `make repair`: one Snakemake build of this folder that heals itself.

    python -m stickslip.pipeline.build [--deep] [--in FOLDER] [--] SNAKEMAKE [ARGS...]

* **One build per folder.** The build holds an exclusive lock (``.snakemake/stickslip-build.lock``, flock: the
  kernel drops it when the build dies, even by ``kill -9``); a second build is told "another build is
  running in this folder" and exits 1. Snakemake's own lock of a build that was killed is removed (no
  Snakemake process is running in this folder), so nobody needs ``--unlock``.
* **Nothing left half-done.** Snakemake runs with ``--rerun-incomplete``: the outputs of a job that was
  killed are rebuilt without a flag.
* **Nothing damaged kept.** Every result the last build wrote is checked against its recorded size and
  checksum (``stickslip.pipeline.integrity``: a stat per file; bytes are read only for a file whose stat
  moved) and rebuilt with ``--forcerun`` if it changed. ``--deep`` (`make repair`) also verifies every
  dataset's own content checksum (``python -m stickslip.io.netcdf verify``), reading all data.
* **A configuration's own folder.** ``--in FOLDER`` (``make small``) builds in FOLDER, which links the
  project's code and config (``PROJECT_LINKS``) and so holds only its own ``results/``: a configuration
  with overlays never writes into the full build's (``stickslip.pipeline.results_owner``).
* **Nothing missing.** Every catalogue dataset a rule names is a target of rule ``all``, and a recorded file
  that is gone is forcerun too (the outputs of rules with wildcards).
"""

from __future__ import annotations

import fcntl
import os
import re
import subprocess
import sys
import time
from pathlib import Path

from . import integrity

LOCK = Path(".snakemake") / "stickslip-build.lock"
RESULTS = Path("results")
BUSY = "another build is running in this folder"


def _snakemake_running_here() -> list[int]:
    """Pids of Snakemake processes whose working directory is this folder (Linux /proc; none elsewhere)."""
    here = os.path.realpath(".")
    pids = []
    for entry in Path("/proc").glob("[0-9]*"):
        try:
            if int(entry.name) == os.getpid() or os.path.realpath(entry / "cwd") != here:
                continue
            if b"snakemake" in (entry / "cmdline").read_bytes():
                pids.append(int(entry.name))
        except (OSError, ValueError):
            continue
    return pids


def _clear_stale_snakemake_lock() -> bool:
    """Remove the lock a killed Snakemake left (False: a Snakemake is running here, leave it)."""
    locks = Path(".snakemake") / "locks"
    stale = [p for p in locks.glob("*.lock")] if locks.is_dir() else []
    if not stale:
        return True
    if _snakemake_running_here():
        return False
    for p in stale:
        p.unlink(missing_ok=True)
    print("removed the lock of a build that was stopped before it finished", file=sys.stderr)
    return True


def _producible(argv: list[str], files: list[str]) -> list[str]:
    """The files among ``files`` that some rule of the current config writes: Snakemake refuses to
    ``--forcerun`` any other (a dataset of a scene since removed from the config). One dry run per file left
    out, only when something is damaged or missing."""
    files = list(files)
    while files:
        proc = subprocess.run(
            [*argv, "--dry-run", "--quiet", "--forcerun", *files], capture_output=True, text=True
        )
        unknown = re.search(r"No rule to produce (\S+)", proc.stdout + proc.stderr)
        if unknown is None or unknown[1] not in files:
            return files
        files.remove(unknown[1])
    return files


#: What a folder of ``--in`` links from the project (everything a build reads; results are its own).
PROJECT_LINKS = ("Snakefile", "workflow", "config", "notebooks", "src", "README.md", "docs")


def link_project(folder: Path, project: Path) -> None:
    """Make ``folder`` a place to build the project in: links to its code and config, its own results."""
    folder.mkdir(parents=True, exist_ok=True)
    for name in PROJECT_LINKS:
        link, target = folder / name, (project / name).resolve()
        if link.is_symlink() and link.resolve() == target:
            continue
        if link.is_symlink():
            link.unlink()
        elif link.exists():
            raise SystemExit(f"--in {folder}: {link} exists and is not a link to the project's {name}")
        link.symlink_to(target)


def _options(argv: list[str]) -> tuple[bool, Path | None, list[str]]:
    deep, folder = False, None
    while argv[:1] in (["--deep"], ["--in"]):
        if argv[0] == "--deep":
            deep, argv = True, argv[1:]
        elif len(argv) < 2:
            raise SystemExit("--in needs a folder")
        else:
            folder, argv = Path(argv[1]), argv[2:]
    return deep, folder, argv[1:] if argv[:1] == ["--"] else argv


def main(argv: list[str]) -> int:
    deep, folder, argv = _options(argv)
    if not argv:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    if folder is not None:
        link_project(folder, Path.cwd())
        os.chdir(folder)
    LOCK.parent.mkdir(parents=True, exist_ok=True)
    lock = open(LOCK, "a+")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        print(f"{BUSY} ({Path.cwd()}): wait for it to finish", file=sys.stderr)
        return 1
    if not _clear_stale_snakemake_lock():
        print(f"{BUSY} ({Path.cwd()}): a Snakemake started outside make holds it", file=sys.stderr)
        return 1

    bad, entries = integrity.damaged()
    if deep and RESULTS.is_dir():
        from ..io.netcdf import verify

        datasets = sorted(p for p in RESULTS.rglob("*.nc") if not p.name.startswith("."))
        bad = sorted(set(bad) | {path for path, _ in verify(datasets)})
    if bad:
        kept = _producible(argv, bad)
        for path in set(bad) - set(kept):  # no rule writes it any more: not ours to check
            entries.pop(path, None)
        bad = kept
    if bad:
        print("rebuilding (missing, or changed since their rule wrote them):", *bad, file=sys.stderr)
    start = time.time_ns()
    cmd = [*argv, "--rerun-incomplete", *(["--forcerun", *bad] if bad else [])]
    rc = subprocess.call(cmd)
    if rc == 0 and RESULTS.is_dir() and "-n" not in argv and "--dry-run" not in argv:
        integrity.record(RESULTS, start, entries)
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
