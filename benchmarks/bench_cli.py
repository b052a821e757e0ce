"""How long `stickslip run` takes from the shell, the issue's target being under 5 s after a build.

Runs the console command as a user types it (a new interpreter each time, so imports count) a few times and
prints wall and CPU time (the child's user + system) per command: `stickslip run --mu-s 0.6 --damping 1.0`
(the baseline's metrics read from results/ when built, else computed in the same call), the same with a
Stribeck law (switch solver), and `python -c "import stickslip"` as the floor of a start. The machine's load
average is printed: on a shared machine wall time exceeds CPU time by what the other processes take.

    .venv/bin/python benchmarks/bench_cli.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
COMMANDS = {
    "import stickslip": [sys.executable, "-c", "import stickslip"],
    "run --mu-s 0.6 --damping 1.0": [str(BIN / "stickslip"), "run", "--mu-s", "0.6", "--damping", "1.0"],
    "run --law stribeck": [str(BIN / "stickslip"), "run", "--law", "stribeck", "mu_k=0.3", "v_s=0.5"],
}


def timed(cmd: list[str]) -> tuple[float, float]:
    """(wall, CPU) seconds of one run of ``cmd`` in the project folder."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    built = (ROOT / "results" / "onedof" / "fig02").is_dir()
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; baseline from a build: {built}")
    print(f"{'command':32s} {'wall min [s]':>12s} {'wall median':>12s} {'CPU median':>11s}")
    for label, cmd in COMMANDS.items():
        runs = sorted(timed(cmd) for _ in range(args.repeats))
        walls = sorted(w for w, _ in runs)
        cpus = sorted(c for _, c in runs)
        mid = len(runs) // 2
        print(f"{label:32s} {walls[0]:12.2f} {walls[mid]:12.2f} {cpus[mid]:11.2f}")


if __name__ == "__main__":
    main()
