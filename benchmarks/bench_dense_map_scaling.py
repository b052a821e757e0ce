"""How the dense map's wall time scales with local cores (snakemake -j1 vs -j2), and its cost per map point.

Runs the configured dense map (config/dense_map.yaml; --quick: a 16 x 16 grid) from scratch in a throw-away
copy of the project, once per job count, in the same process run, and prints: jobs, wall time of the whole
Snakemake run (chunks + merge), speed-up over -j1, wall time per point, summed CPU time of the chunk jobs
(from their benchmark files) per point, and the in-process cost of one exact-solver run plus its metrics
(no Snakemake, no file I/O) as the floor. The machine's load average is printed: on a shared machine the
-j2 speed-up is bounded by the cores that are actually free.

    .venv/bin/python benchmarks/bench_dense_map_scaling.py [--quick] [--jobs 1 2] [--map speed_damping]
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

from stickslip import catalogue as paths
from stickslip.schema import PipelineConfig
from stickslip.studies.specs import dense_map

ROOT = Path(__file__).resolve().parents[1]


def clone_project(dest: Path) -> Path:
    """The committed project (no results) in ``dest``: what a user who clones the repository runs."""
    subprocess.run(["git", "clone", "--quiet", str(ROOT), str(dest)], check=True)
    return dest


def pipeline_config(extra: list[Path]) -> dict:
    def merge(a, b):
        for k, v in b.items():
            a[k] = merge(a.get(k, {}), v) if isinstance(v, dict) and isinstance(a.get(k), dict) else v
        return a

    config = {}
    for path in sorted((ROOT / "config").glob("*.yaml")) + extra:
        merge(config, yaml.safe_load(path.read_text()))
    return config


def floor_cost(dm, n: int = 60) -> float:
    """Seconds per point of run_points alone, over n points spread across the grid."""
    from stickslip.analysis.sweep import chunk_points

    every = max(1, dm.points // n)
    points = [p for i in range(0, dm.points, every) for p in chunk_points(dm.axes, 1, i)][:n]
    start = time.process_time()
    dm.run(points)
    return (time.process_time() - start) / len(points)


def chunk_cpu(work: Path, name: str) -> tuple[float, int]:
    total, count = 0.0, 0
    for tsv in (work / "results" / "benchmarks" / "dense_map_chunk" / name).glob("*.tsv"):
        with tsv.open() as fh:
            row = next(csv.DictReader(fh, delimiter="\t"))
        total += float(row["cpu_time"]) if row.get("cpu_time", "NA") not in ("NA", "") else float(row["s"])
        count += 1
    return total, count


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--quick", action="store_true", help="16 x 16 grid in 8 chunks instead of the configured map"
    )
    ap.add_argument("--jobs", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--map", default="speed_damping")
    args = ap.parse_args()

    with tempfile.TemporaryDirectory(prefix="bench_dense_map_") as tmp:
        work = clone_project(Path(tmp) / "clone")
        extra = []
        if args.quick:
            quick = work / "bench_quick.yaml"
            cfg = pipeline_config([])["dense_map"]["maps"][args.map]
            axes = [{**a, "num": 16} if "num" in a else a for a in cfg["axes"]]
            quick.write_text(
                yaml.safe_dump({"dense_map": {"chunk_size": 32, "maps": {args.map: {"axes": axes}}}})
            )
            extra = [quick]
        typed = PipelineConfig.model_validate(pipeline_config(extra))
        dm = dense_map(typed.onedof, typed.dense_map, args.map)
        print(
            f"map {args.map}: {' x '.join(str(len(a.values)) for a in dm.axes)} = {dm.points} points, "
            f"{dm.chunks} chunks of {dm.chunk_size}, t_end {dm.spec.t_end:g} s, solver {dm.spec.method}; "
            f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at start"
        )
        floor = floor_cost(dm)
        target = paths.dense_map(args.map)
        rows = []
        for jobs in args.jobs:
            shutil.rmtree(work / "results", ignore_errors=True)
            shutil.rmtree(work / ".snakemake", ignore_errors=True)
            cmd = [
                sys.executable,
                "-m",
                "snakemake",
                f"-j{jobs}",
                "--directory",
                str(work),
                "--snakefile",
                str(work / "Snakefile"),
                "--quiet",
            ]
            if extra:
                cmd += ["--configfile", *map(str, extra)]
            load = os.getloadavg()[0]
            start = time.perf_counter()
            proc = subprocess.run([*cmd, "--", target], capture_output=True, text=True)
            wall = time.perf_counter() - start
            if proc.returncode != 0:
                raise SystemExit(f"snakemake -j{jobs} failed:\n{proc.stderr[-3000:]}")
            cpu, chunks = chunk_cpu(work, args.map)
            assert chunks == dm.chunks, (chunks, dm.chunks)
            rows.append((jobs, wall, cpu, load))

    base = rows[0][1]
    print()
    print(
        f"{'jobs':>4} {'wall [s]':>9} {'speed-up':>9} {'wall/pt [ms]':>13} {'chunk CPU [s]':>14} "
        f"{'CPU/pt [ms]':>12} {'load':>5}"
    )
    for jobs, wall, cpu, load in rows:
        print(
            f"{jobs:>4} {wall:9.1f} {base / wall:9.2f} {1e3 * wall / dm.points:13.2f} {cpu:14.1f} "
            f"{1e3 * cpu / dm.points:12.2f} {load:5.1f}"
        )
    print(
        f"floor: one exact run + metrics in-process = {1e3 * floor:.2f} ms CPU per point "
        f"(=> {floor * dm.points:.1f} s CPU for the map; 200 x 200 = {floor * 40000 / 60:.1f} CPU-minutes)"
    )
    print("speed-up = wall(-j1) / wall(-jN) measured in this run; chunk CPU from Snakemake benchmark files")


if __name__ == "__main__":
    main()
