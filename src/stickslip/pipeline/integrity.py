"""Which results changed since the build that wrote them, found from a stat in the common case.

After every successful build the record ``.snakemake/stickslip-integrity.json`` holds, per file of
``results/`` (logs, benchmark timings and hidden temporaries aside, as ``stickslip.io.compare`` leaves
them out): size, mtime, ctime, inode and the sha256 of its bytes. The next build checks every recorded file:

* the same size, mtime, ctime and inode: unchanged, nothing read (a no-op build reads no data);
* another size: damaged;
* the same size but another stat (a byte written with its mtime put back still moves the ctime, which no
  program can set; a copied tree moves every inode): its bytes are hashed again, and damaged only if the
  hash differs (else the new stat is recorded).

A damaged file is rebuilt with ``--forcerun``, which also re-runs what reads it; so is a recorded file that is
gone (every catalogue dataset a rule names is a target of rule ``all`` and Snakemake rebuilds it anyway; the
outputs of rules with wildcards are not, and an intermediate one would stay gone). ``--forcerun`` of a file
the current config no longer builds does nothing.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

#: The record, beside Snakemake's own metadata (`make clean` removes both).
RECORD = Path(".snakemake") / "stickslip-integrity.json"
#: Top-level folders of results/ that hold one build's own narrative, not results (as stickslip.io.compare).
SKIPPED_FOLDERS = ("logs", "benchmarks")


def _stat_key(st: os.stat_result) -> list[int]:
    return [st.st_size, st.st_mtime_ns, st.st_ctime_ns, st.st_ino]


def sha256(path: Path) -> str:
    with open(path, "rb") as f:
        return hashlib.file_digest(f, "sha256").hexdigest()


def result_files(results: Path) -> list[Path]:
    """Every file of ``results`` the record covers (paths as given, i.e. relative when ``results`` is)."""
    out = []
    for folder, dirs, files in os.walk(results):
        rel = Path(folder).relative_to(results)
        if rel.parts[:1] and rel.parts[0] in SKIPPED_FOLDERS:
            dirs[:] = []
            continue
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        out += [Path(folder, f) for f in files if not f.startswith(".")]
    return sorted(out)


def load(record: Path = RECORD) -> dict[str, dict]:
    try:
        return json.loads(record.read_text())
    except (OSError, ValueError):  # none yet, or unreadable: nothing is known, nothing is flagged
        return {}


def damaged(record: Path = RECORD) -> tuple[list[str], dict[str, dict]]:
    """(files missing or whose bytes differ from what the last build recorded, the record with refreshed
    stats)."""
    entries = load(record)
    bad = []
    for path, entry in sorted(entries.items()):
        try:
            st = os.stat(path)
        except FileNotFoundError:
            bad.append(path)
            continue
        key = _stat_key(st)
        if key == entry["stat"]:
            continue
        if st.st_size != entry["stat"][0] or sha256(Path(path)) != entry["sha256"]:
            bad.append(path)
        else:
            entry["stat"] = key
    return bad, entries


def record(results: Path, since_ns: int, entries: dict[str, dict], record: Path = RECORD) -> int:
    """Record every file of ``results`` written at or after ``since_ns`` (a build's start) or not recorded
    yet; a file the build did not write keeps its entry (a damaged one stays damaged). Returns how many
    files were hashed."""
    hashed = 0
    out = {}
    for path in result_files(results):
        name = str(path)
        st = os.stat(path)
        old = entries.get(name)
        if old is not None and (old["stat"] == _stat_key(st) or st.st_mtime_ns < since_ns):
            out[name] = old
            continue
        out[name] = {"stat": _stat_key(st), "sha256": sha256(path)}
        hashed += 1
    record.parent.mkdir(parents=True, exist_ok=True)
    tmp = record.with_name(f".{record.name}.tmp")
    tmp.write_text(json.dumps(out, indent=0, sort_keys=True))
    os.replace(tmp, record)
    return hashed
