"""Bit identity of the explicit engine on THIS machine, before and after a refactoring.

The test suite compares the engine with stored references within measured round-off tolerances
(tests/fe/test_engine_references.py), because bits depend on the CPU. A refactoring that must not change
any bit (a new structure for the same arithmetic) is checked here instead: record the digests of every
output array of the regression cases (tests/fe/engine_cases.py) before the change, compare after it, on
the same machine and environment (same CPU, same NUMBA_CPU_NAME, same lock).

    .venv/bin/python benchmarks/check_engine_bits.py record  [--file results/engine_bits.json] [CASE ...]
    .venv/bin/python benchmarks/check_engine_bits.py compare [--file results/engine_bits.json] [CASE ...]

``record`` writes the digests with the machine's CPU description; ``compare`` exits 1 listing every array
that differs (and warns when the file was written on another CPU, where differences are expected).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "fe"))

from engine_cases import case_mappings, run_case  # noqa: E402

ARRAYS = ("t", "x", "y", "vx", "vy", "normal_force", "friction_force", "slip_velocity", "state")


def digest(a) -> str:
    a = np.ascontiguousarray(a)
    h = hashlib.sha256(str((a.dtype.str, a.shape)).encode())
    h.update(a.tobytes())
    return h.hexdigest()[:24]


def run_digests(r) -> dict:
    d = {name: digest(getattr(r, name)) for name in ARRAYS}
    for name in ("q_samples", "v_samples"):
        if getattr(r, name) is not None:
            d[name] = digest(getattr(r, name))
    d["scalars"] = repr((r.dt, r.n_steps, r.step_counts, r.extra.get("second_half_counts")))
    d["diverged"] = bool(r.extra["diverged"])
    return d


def machine() -> str:
    import numba

    cpu = numba.config.CPU_NAME or __import__("llvmlite.binding", fromlist=["x"]).get_host_cpu_name()
    model = ""
    try:
        model = next(
            ln.split(":", 1)[1].strip() for ln in open("/proc/cpuinfo") if ln.startswith("model name")
        )
    except (OSError, StopIteration):
        pass
    return (
        f"{platform.machine()} {model} numba-cpu={cpu} NUMBA_CPU_NAME={os.environ.get('NUMBA_CPU_NAME', '')}"
    )


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("action", choices=("record", "compare"))
    ap.add_argument("cases", nargs="*", help="case names (default: all)")
    ap.add_argument("--file", type=Path, default=ROOT / "results" / "engine_bits.json")
    a = ap.parse_args(argv)
    names = a.cases or list(case_mappings())
    now = {}
    for name in names:
        now[name] = run_digests(run_case(name))
        print(name, file=sys.stderr)
    if a.action == "record":
        a.file.parent.mkdir(parents=True, exist_ok=True)
        a.file.write_text(json.dumps({"machine": machine(), "cases": now}, indent=1, sort_keys=True) + "\n")
        print(f"recorded {len(now)} cases in {a.file} ({machine()})")
        return 0
    old = json.loads(a.file.read_text())
    if old["machine"] != machine():
        print(
            f"warning: recorded on {old['machine']!r}, this is {machine()!r}: bits may differ",
            file=sys.stderr,
        )
    bad = [
        f"{name}: {key}"
        for name, d in now.items()
        for key in sorted(set(d) | set(old["cases"].get(name, {})))
        if d.get(key) != old["cases"].get(name, {}).get(key)
    ]
    print("\n".join(bad) if bad else f"all {len(now)} cases bit-identical to {a.file}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
