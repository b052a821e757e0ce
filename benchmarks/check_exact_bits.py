"""Bit identity of the exact 1-DOF solver on THIS machine, before and after a change that must not move a bit.

The test suite checks the exact solver against closed forms and peers within tolerances (bits depend on the
CPU). A change of structure for the same arithmetic is checked here instead: record the digests of every
trajectory of a seeded set of runs before the change, compare after it, on the same machine and environment.
The runs cover every friction variant (consistent, Eq. 3 and Eq. 4 as printed), decelerating belts, friction
plateaus and the inverse study's static/kinetic solver, over log-uniform parameters; a run that raises is
recorded by its error's type.

    .venv/bin/python benchmarks/check_exact_bits.py record  [--file results/exact_bits.json] [--runs N]
    .venv/bin/python benchmarks/check_exact_bits.py compare [--file results/exact_bits.json] [--runs N]

Both print the solver's CPU time over the runs (process time, the sampling included), so a speed change is
measured in the same command; ``compare`` exits 1 listing every run whose trajectory differs.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import platform
import sys
import time
from pathlib import Path

import numpy as np

from stickslip.inverse.forward import build_model
from stickslip.model.equations import BeltModel
from stickslip.model.friction import friction_law
from stickslip.model.params import BeltParams
from stickslip.solvers.exact import ExactSwitchSolver

ROOT = Path(__file__).resolve().parents[1]
VARIANTS = ("consistent", "eq3_printed", "eq4_printed")
T_END = 20.0


def cases(runs: int, seed: int = 1):
    """(label, model, solver) of ``runs`` seeded parameter sets; a fifth use the static/kinetic solver."""
    rng = np.random.default_rng(seed)
    for i in range(runs):
        if i % 5 == 4:
            p = BeltParams(
                mass=1.0,
                stiffness=10 ** rng.uniform(0, 1.2),
                damping=10 ** rng.uniform(-1, 0.5),
                mu_s=rng.uniform(0.2, 1.0),
                sigma=10 ** rng.uniform(-1.5, 0),
                normal_force=10.0,
            )
            model, solver = build_model(p, "consistent", mu_k_ratio=rng.uniform(0.6, 1.0))
            yield f"{i}:static_kinetic", model, solver
            continue
        kw = dict(
            mass=10 ** rng.uniform(-1, 1),
            stiffness=10 ** rng.uniform(-0.3, 1.7),
            damping=10 ** rng.uniform(-2, 1),
            mu_s=rng.uniform(0.1, 1.2),
            sigma=10 ** rng.uniform(-2, 0.3),
            normal_force=10 ** rng.uniform(0, 2),
            belt_velocity=rng.uniform(0.1, 2.0),
        )
        if i % 4 == 1:
            kw["belt_deceleration"] = rng.uniform(0.01, 0.2)
        if i % 3 == 2:
            kw["plateau_speed"] = rng.uniform(0.1, 3.0)
        variant = VARIANTS[i % len(VARIANTS)]
        p = BeltParams(**kw)
        yield f"{i}:{variant}", BeltModel(p, friction_law(p, variant)), ExactSwitchSolver()


def digest(*arrays) -> str:
    h = hashlib.sha256()
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(str((a.dtype.str, a.shape)).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:24]


def run_all(runs: int) -> tuple[dict[str, str], float]:
    """label -> digest of (t, x, v, phase, ok), and the CPU seconds of the solves."""
    out, cpu = {}, 0.0
    t_eval = np.linspace(0.0, T_END, 2001)
    _, model, solver = next(cases(1))
    solver.solve(model, T_END, t_eval)  # untimed: the solver's lazy imports (scipy.optimize) are no solve
    for label, model, solver in cases(runs):
        start = time.process_time()
        try:
            with np.errstate(all="ignore"):  # runs that grow without bound are recorded, not warned about
                traj = solver.solve(model, T_END, t_eval)
            out[label] = digest(traj.t, traj.x, traj.v, traj.phase, np.array([traj.ok]))
        except Exception as exc:  # a refused parameter set is a result too: its error type must not change
            out[label] = f"raises {type(exc).__name__}"
        cpu += time.process_time() - start
    return out, cpu


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("action", choices=("record", "compare"))
    parser.add_argument("--file", type=Path, default=ROOT / "results" / "exact_bits.json")
    parser.add_argument("--runs", type=int, default=300)
    args = parser.parse_args(argv)
    digests, cpu = run_all(args.runs)
    ok = sum(not d.startswith("raises") for d in digests.values())
    print(f"{len(digests)} runs ({ok} solved), solver CPU {cpu:.2f} s")
    if args.action == "record":
        args.file.parent.mkdir(parents=True, exist_ok=True)
        args.file.write_text(json.dumps({"cpu": platform.processor() or platform.machine(), "runs": digests}))
        print(f"recorded in {args.file}")
        return 0
    stored = json.loads(args.file.read_text())
    differ = sorted(k for k in stored["runs"] if stored["runs"][k] != digests.get(k))
    listed = f": {', '.join(differ[:10])}" if differ else ""
    print(f"{len(differ)} of {len(stored['runs'])} runs differ{listed}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
