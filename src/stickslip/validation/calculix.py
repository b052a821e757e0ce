"""Run CalculiX (``ccx``) on a deck of ``stickslip.fe.abaqus_deck`` and read its ``.dat`` output.

ccx exits with status 0 even when it stops on an error, so a run counts as failed when its output has an
``*ERROR`` line, when the ``.dat`` file is missing, or when the ``.dat`` lacks what was asked for; every
failure is a ``CalculixError`` naming the scene (the deck's name) and quoting ccx's message.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: the Debian package that provides ccx (named in every "not found" error)
CCX_PACKAGE = "calculix-ccx"


class CalculixError(RuntimeError):
    """ccx missing, failing, or its output missing what the deck asked for."""


def ccx_executable(scene: str, name: str = "ccx") -> str:
    """The path of ``ccx`` on PATH, or a ``CalculixError`` saying what is missing and how to install it."""
    path = shutil.which(name)
    if path is None:
        raise CalculixError(
            f"{scene}: the CalculiX solver '{name}' is not on PATH, so the CalculiX peer cannot run; install "
            f"it with `apt-get install -y {CCX_PACKAGE}` (Debian/Ubuntu)"
        )
    return path


def run_ccx(
    deck: str, scene: str, *, workdir: str | os.PathLike | None = None, timeout: float = 600.0
) -> str:
    """Run ccx on ``deck`` (text) as job ``scene`` in ``workdir`` (default: a temporary folder, removed
    afterwards); returns the ``.dat`` text."""
    exe = ccx_executable(scene)
    if workdir is None:
        with tempfile.TemporaryDirectory(prefix=f"ccx_{scene}_") as tmp:
            return run_ccx(deck, scene, workdir=tmp, timeout=timeout)
    work = Path(workdir)
    work.mkdir(parents=True, exist_ok=True)
    (work / f"{scene}.inp").write_text(deck)
    env = {**os.environ, "OMP_NUM_THREADS": "1", "CCX_NPROC_EQUATION_SOLVER": "1"}
    try:
        proc = subprocess.run(
            [exe, "-i", scene], cwd=work, capture_output=True, text=True, timeout=timeout, env=env
        )
    except subprocess.TimeoutExpired as err:
        raise CalculixError(f"{scene}: ccx did not finish within {timeout:g} s") from err
    log = proc.stdout + proc.stderr
    errors = [ln.strip() for ln in log.splitlines() if "*ERROR" in ln]
    if proc.returncode != 0 or errors:
        tail = "\n".join(log.strip().splitlines()[-8:])
        what = "; ".join(errors) or "no *ERROR line"
        raise CalculixError(f"{scene}: ccx failed (exit status {proc.returncode}): {what}\n{tail}")
    dat = work / f"{scene}.dat"
    if not dat.is_file():
        raise CalculixError(f"{scene}: ccx wrote no {dat.name}")
    return dat.read_text()


# ------------------------------------------------------------------------------------------------ .dat
@dataclass
class DatBlock:
    """One printed table of a ``.dat`` file: what (``displacements``, ``forces``, ``total force``), for
    which node set, in which eigenmode (0: not a frequency step), and its rows (node -> values; the total
    under node 0)."""

    what: str
    nset: str
    mode: int
    rows: dict = field(default_factory=dict)


@dataclass
class DatResult:
    frequencies: list  #: [Hz] per frequency step, in order: one list each
    blocks: list  #: DatBlock, in file order


_FLOAT = r"[-+]?\d+\.\d*(?:[eE][-+]?\d+)?"
_EIGEN_ROW = re.compile(rf"^\s*(\d+)\s+({_FLOAT})\s+({_FLOAT})\s+({_FLOAT})\s+({_FLOAT})\s*$")
_HEAD = re.compile(r"^\s*(displacements|forces|total force) \(\w+,\w+,\w+\) for set (\S+) and time")
_MODE = re.compile(r"E I G E N V A L U E\s+N U M B E R\s+(\d+)")


def parse_dat(text: str) -> DatResult:
    """Frequencies (cycles/time column of each EIGENVALUE OUTPUT table) and node tables of a ccx .dat file."""
    freqs: list[list[float]] = []
    blocks: list[DatBlock] = []
    mode, in_eigen, current = 0, False, None
    for line in text.splitlines():
        if "E I G E N V A L U E   O U T P U T" in line:
            freqs.append([])
            in_eigen, current, mode = True, None, 0
            continue
        if in_eigen:
            m = _EIGEN_ROW.match(line)
            if m:
                freqs[-1].append(float(m.group(4)))
                continue
            if "P A R T I C I P A T I O N" in line or _HEAD.match(line) or _MODE.search(line):
                in_eigen = False
            else:
                continue
        m = _MODE.search(line)
        if m:
            mode, current = int(m.group(1)), None
            continue
        m = _HEAD.match(line)
        if m:
            current = DatBlock(m.group(1), m.group(2).upper(), mode)
            blocks.append(current)
            continue
        fields = line.split()
        if current is not None and fields:
            try:
                values = [float(v) for v in fields]
            except ValueError:
                current = None
                continue
            if current.what == "total force":
                current.rows[0] = tuple(values)
            elif len(values) == 4:
                current.rows[int(values[0])] = tuple(values[1:])
    return DatResult(freqs, blocks)


def static_block(result: DatResult, what: str, nset: str, scene: str) -> dict:
    """The last table ``what`` of set ``nset`` outside a frequency step (the static step's)."""
    found = [b for b in result.blocks if b.what == what and b.nset == nset.upper()]
    static = [b for b in found if b.mode == 0]
    if not static:
        raise CalculixError(f"{scene}: the .dat has no static '{what}' table for node set {nset}")
    return static[-1].rows


def mode_blocks(result: DatResult, nset: str) -> dict:
    """mode number -> displacement rows of set ``nset`` (the frequency step's per-mode tables)."""
    return {
        b.mode: b.rows
        for b in result.blocks
        if b.what == "displacements" and b.nset == nset.upper() and b.mode
    }


# ---------------------------------------------------------------------------------------- time series
_SERIES_HEAD = re.compile(
    r"^\s*(displacements|forces|total force|total kinetic energy|total internal energy)"
    r"(?: \(\w+,\w+,\w+\))? for set (\S+) and time\s+(\S+)"
)


def dat_time_series(text: str) -> dict:
    """Every printed table of a transient ccx ``.dat`` as time series: ``(what, NSET) -> (times (n,),
    values (n, k))``; node tables hold the mean over the set's nodes (k = 3), totals their k values."""
    series: dict = {}
    key, rows = None, []

    def flush():
        if key is not None and rows:
            vals = np.array(rows, float)
            if key[0] in ("displacements", "forces"):
                vals = vals[:, 1:]  # drop the node number
            series.setdefault(key[:2], []).append((key[2], vals.mean(axis=0)))

    for line in text.splitlines():
        m = _SERIES_HEAD.match(line)
        if m:
            flush()
            key, rows = (m.group(1), m.group(2).upper(), float(m.group(3))), []
            continue
        fields = line.split()
        if key is None or not fields:
            continue
        try:
            rows.append([float(v) for v in fields])
        except ValueError:
            flush()
            key, rows = None, []
    flush()
    out = {}
    for k, pts in series.items():
        t = np.array([p[0] for p in pts])
        v = np.array([p[1] for p in pts])
        # ccx prints a converged increment once; a reattempted increment is not printed twice, but keep
        # the last value of any repeated time
        _, last = np.unique(t[::-1], return_index=True)
        idx = np.sort(len(t) - 1 - last)
        out[k] = (t[idx], v[idx])
    return out
