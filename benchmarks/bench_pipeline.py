"""What a new user waits for: clean build, no-op rerun and test suite, timed on a fresh clone in one run.

    python benchmarks/bench_pipeline.py            # clone HEAD into a temp folder, time the README commands
    python benchmarks/bench_pipeline.py --no-test  # only the clean build and the no-op rerun
    python benchmarks/bench_pipeline.py --record   # ... and write this run's per-rule CPU into docs/TIMING.md

Steps, each in the fresh clone, exactly as the README gives them:
1. ``make figures`` from nothing (creates .venv from the lock, runs ``snakemake -j2``): the clean build;
2. ``make figures`` again: the no-op rerun (must find nothing to do);
3. ``rm -rf .venv results .snakemake`` then ``make test``: README command 2 from a clean state.

Prints the elapsed (wall) and CPU time (this process's children: every job, the installs) of each step
against the targets, and the per-rule table of the clean build from its Snakemake benchmark files: each
rule's CPU against its budget in docs/TIMING.md and the change from the last recorded run, so a rule that
got slower is seen in the round that made it so. ``--record`` writes this run's CPU into that table as the
last recorded one (budgets are edited by hand, with a reason in the commit).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

from stickslip.io.benchmarks import (  # installed: `make bench` runs .venv python
    budget_rows,
    budget_table,
    read_budgets,
    summarize_benchmarks,
    with_budget_table,
)

ROOT = Path(__file__).resolve().parents[1]

#: Targets on the project's reference machine (2 cores, nothing else running): seconds of elapsed time, and
#: of CPU where one is set (docs/TIMING.md).
TARGETS = {"clean make figures": 300.0, "no-op make figures": 3.0, "clean make test": 300.0}
CPU_TARGETS = {"clean make figures": 550.0}
TIMING = ROOT / "docs" / "TIMING.md"


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(label: str, cmd: list[str], cwd: Path, log: Path) -> dict:
    cpu0, t0 = children_cpu(), time.perf_counter()
    with log.open("w") as fh:
        proc = subprocess.run(cmd, cwd=cwd, stdout=fh, stderr=subprocess.STDOUT)
    wall, cpu = time.perf_counter() - t0, children_cpu() - cpu0
    print(f"  {label}: exit {proc.returncode}, {wall:.1f} s elapsed, {cpu:.1f} s CPU (log {log})", flush=True)
    if proc.returncode:  # the temporary folder goes at the end: show why here
        print("    " + "\n    ".join(log.read_text().splitlines()[-40:]), flush=True)
    return {"step": label, "exit": proc.returncode, "wall_s": wall, "cpu_s": cpu}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--no-test", action="store_true", help="skip step 3 (make test)")
    ap.add_argument(
        "--keep", action="store_true", help="keep the clone and the clean build's results (paths printed)"
    )
    ap.add_argument("--record", action="store_true", help="write this run's per-rule CPU into docs/TIMING.md")
    args = ap.parse_args(argv)

    work = Path(tempfile.mkdtemp(prefix="bench_pipeline_"))
    clone = work / "clone"
    subprocess.run(["git", "clone", "--quiet", str(ROOT), str(clone)], check=True)
    shared = ROOT.parent / "shared"
    if shared.is_dir() and not (work / "shared").exists():
        os.symlink(shared, work / "shared")  # the paper's text, where the README points
    rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=clone, capture_output=True, text=True)
    print(f"fresh clone of {rev.stdout.strip()} in {clone} ({os.cpu_count()} cores)", flush=True)

    rows = [timed("clean make figures", ["make", "figures"], clone, work / "figures.log")]
    rule_rows = summarize_benchmarks(clone / "results" / "benchmarks")
    rows.append(timed("no-op make figures", ["make", "figures"], clone, work / "noop.log"))
    if not args.no_test:
        if args.keep:  # the clean build's results, for `python -m stickslip.io.compare` with another build
            (clone / "results").rename(work / "results_clean_build")
        for name in (".venv", "results", ".snakemake"):
            shutil.rmtree(clone / name, ignore_errors=True)
        rows.append(timed("clean make test", ["make", "test"], clone, work / "test.log"))

    print("\n| step | exit | elapsed [s] | CPU [s] | target [s] | elapsed / target | CPU target [s] |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        target, cpu_target = TARGETS[r["step"]], CPU_TARGETS.get(r["step"])
        print(
            f"| {r['step']} | {r['exit']} | {r['wall_s']:.1f} | {r['cpu_s']:.1f} | {target:.0f} | "
            f"{r['wall_s'] / target:.2f} | {'' if cpu_target is None else f'{cpu_target:.0f}'} |"
        )
    print("\nClean build, per rule (Snakemake benchmark files; jobs run two at a time):\n")
    print("| rule | jobs | job wall sum [s] | job CPU sum [s] | longest job [s] | peak RSS [MB] |")
    print("|---|---|---|---|---|---|")
    for r in sorted(rule_rows, key=lambda r: -r["cpu_s_total"]):
        print(
            f"| {r['rule']} | {r['jobs']} | {r['wall_s_total']:.1f} | {r['cpu_s_total']:.1f} | "
            f"{r['wall_s_max']:.1f} | {r['peak_rss_mb']:.0f} |"
        )
    wall = sum(r["wall_s_total"] for r in rule_rows)
    cpu = sum(r["cpu_s_total"] for r in rule_rows)
    print(f"| **total** | {sum(r['jobs'] for r in rule_rows)} | {wall:.1f} | {cpu:.1f} | | |")

    budgets = read_budgets(TIMING.read_text())
    checked = budget_rows(rule_rows, budgets)
    print("\nPer rule against its budget (docs/TIMING.md) and the last recorded run:\n")
    print("| rule | CPU [s] | budget [s] | CPU / budget | last recorded [s] | change [s] |")
    print("|---|---|---|---|---|---|")
    for r in sorted(checked, key=lambda r: -(r["cpu_s"] if r["cpu_s"] == r["cpu_s"] else -1)):
        flag = " **over**" if r["over"] else ""
        print(
            f"| {r['rule']} | {r['cpu_s']:.1f} | {r['budget_s']:g} | {r['ratio']:.2f}{flag} | "
            f"{r['last_s']:.1f} | {r['change_s']:+.1f} |"
        )
    if args.record:
        TIMING.write_text(with_budget_table(TIMING.read_text(), budget_table(checked, rev.stdout.strip())))
        print(f"\nrecorded this run's per-rule CPU in {TIMING}")
    if args.keep:
        print(f"\nclone kept: {clone}; the clean build's results: {work / 'results_clean_build'}")
    else:
        shutil.rmtree(work, ignore_errors=True)
    return 0 if all(r["exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
