"""The compiled exact solver (method ``exact``) against its pure-Python reference, measured in one run.

Rows: one forward run as the pipeline makes it (the baseline scene fig02 x consistent_caption, 40 s, 4001
samples; the plateau reading; the si reading, 40001 samples; the decelerating belt), one run of the inverse
study's forward model (``inverse.forward``: the solve, then ``observe``), and one whole forward evaluation of
an inverse problem (all its runs). CPU time per call (process time, best of ``--repeats`` batches) and the
ratio. Then the cost of the first solve in a fresh process: with the on-disk numba cache as it is (warm
after any earlier run) and with an empty cache (``NUMBA_CACHE_DIR`` in a temporary directory: compilation).

    PYTHONPATH=src .venv/bin/python benchmarks/bench_exact_compiled.py [--repeats 5] [--no-cold]
"""

from __future__ import annotations

import argparse
import glob
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml

import stickslip.inverse.forward as forward_module
from stickslip.inverse.forward import Forward, build_model, observe
from stickslip.inverse.problem import build_problem, load_claim_rows
from stickslip.schema import Onedof
from stickslip.solvers.exact_compiled import python_reference
from stickslip.studies.specs import run_spec

ROOT = Path(__file__).resolve().parents[1]

FIRST_SOLVE = """
import time
t0 = time.perf_counter()
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import make_solver
solver, model = make_solver("exact"), BeltModel.build(PAPER_BASELINE.with_(sigma=0.5), "consistent")
t1 = time.perf_counter()
solver.solve(model, 40.0)
t2 = time.perf_counter()
solver.solve(model, 40.0)
t3 = time.perf_counter()
print(t1 - t0, t2 - t1, t3 - t2)
"""


def per_call(fn, repeats: int, batch: int) -> float:
    fn()  # untimed: lazy imports, the kernel's cache load
    best = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        for _ in range(batch):
            fn()
        best = min(best, (time.process_time() - start) / batch)
    return best


def first_solve(cache_dir: str | None) -> tuple[float, float, float]:
    """(import, first solve, second solve) wall seconds in a fresh interpreter."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = cache_dir
    cmd = [sys.executable, "-c", FIRST_SOLVE]
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
    return tuple(float(v) for v in out.stdout.split())


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--no-cold", action="store_true", help="skip the empty-cache compile measurement")
    args = ap.parse_args(argv)
    config = {}
    for name in ("config.yaml", "inverse.yaml"):
        config.update(yaml.safe_load((ROOT / "config" / name).read_text()))
    claims = load_claim_rows(sorted(glob.glob(str(ROOT / "config" / "claims" / "*.yaml"))))
    np.seterr(all="ignore")  # diverging runs are data

    rows = []
    for scene, reading in (
        ("fig02", "consistent_caption"),
        ("fig02", "plateau_caption"),
        ("fig02", "consistent_si"),
        ("fig15", "consistent_caption"),
    ):
        spec = run_spec(Onedof.model_validate(config["onedof"]), scene, reading, "exact")
        compiled = spec.solver()
        python = python_reference(compiled)
        times = [
            per_call(
                lambda solver=solver, spec=spec: solver.solve(spec.model, spec.t_end, spec.t_eval),
                args.repeats,
                20,
            )
            for solver in (python, compiled)
        ]
        rows.append((f"scene {scene} x {reading} ({len(spec.t_eval)} samples)", *times))

    problem = build_problem(config, claims, "fig02", "consistent")
    run, rs = problem.runs[0], problem.run_settings
    model, compiled = build_model(problem.run_params(problem.stated_free, run, {}), problem.variant)
    n = int(round(rs["t_end"] / rs["output_dt"]))
    t_eval = np.linspace(0.0, n * rs["output_dt"], n + 1)
    names = sorted({o.metric for o in problem.observations if o.run == 0})

    def one_run(solver):
        traj = solver.solve(model, rs["t_end"], t_eval)
        return observe(traj, rs["transient"], rs["count_window"], names)

    solvers = (python_reference(compiled), compiled)
    times = [per_call(lambda solver=solver: one_run(solver), args.repeats, 20) for solver in solvers]
    rows.append(("inverse forward run fig02/consistent (solve + observe)", *times))

    for name, family in (("fig02", "consistent"), ("joint", "plateau")):
        problem = build_problem(config, claims, name, family)
        times = []
        for backend in ("python", "compiled"):
            original = forward_module.build_model

            def built(*a, _original=original, _backend=backend, **kw):
                model, solver = _original(*a, **kw)
                return model, (python_reference(solver) if _backend == "python" else solver)

            forward_module.build_model = built
            try:
                fw = Forward(problem)
                step = iter(range(1, 10**6))
                times.append(
                    per_call(
                        lambda fw=fw, step=step, p=problem: fw.measure(
                            p.stated_free * (1 + 1e-6 * next(step))
                        ),
                        args.repeats,
                        3,
                    )
                )
            finally:
                forward_module.build_model = original
        rows.append((f"inverse evaluation {name}/{family} ({len(problem.runs)} runs)", *times))

    print("exact solver: pure Python (reference) vs compiled (numba), CPU ms per call, best of", args.repeats)
    print(f"{'case':62s} {'python':>9s} {'compiled':>9s} {'ratio':>7s}")
    for label, py, jit in rows:
        print(f"{label:62s} {py * 1e3:9.3f} {jit * 1e3:9.3f} {py / jit:7.1f}")

    imp, first, second = first_solve(None)
    print(
        f"\nfresh process, cache as it is: imports {imp:.3f} s, first solve {first:.3f} s "
        f"(numba import + cache load), second {second * 1e3:.2f} ms"
    )
    if not args.no_cold:
        with tempfile.TemporaryDirectory(prefix="numba_cold_") as cold:
            imp, first, second = first_solve(cold)
        print(f"fresh process, empty cache:    first solve {first:.3f} s (compilation)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
