"""Switch-model solver (any law) vs the exact closed-form solver (affine laws only), and its cost per law.

Part 1, the affine baseline (sigma = 0.5, 40 s): the switch solver at several DOP853 tolerances against the
exact solver; largest error of the last-cycle quantities and of the sampled trajectory, CPU time (min over
repeats, process time) and the CPU ratio to the exact solver measured in the same run.
Part 2, every law of config/validation.yaml (60 s runs): switch-solver CPU, phases, RHS evaluations, and
the CVODE peer's CPU for scale.

    PYTHONPATH=src python benchmarks/bench_switch.py [--quick]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np
import yaml

from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.schema import PeerJob
from stickslip.solvers.base import SolverStats
from stickslip.solvers.exact import ExactSwitchSolver, sample_segments
from stickslip.solvers.switch import SwitchSolver
from stickslip.validation.cycle import cycle_quantities, record_from_segments
from stickslip.validation.peer import peer_events
from stickslip.validation.setup import law_model, switch_solver

ROOT = Path(__file__).resolve().parents[1]


def cpu(fn, repeats: int) -> tuple[float, object]:
    best, out = np.inf, None
    for _ in range(repeats):
        start = time.process_time()
        out = fn()
        best = min(best, time.process_time() - start)
    return best, out


def affine_table(repeats: int, t_end: float = 40.0) -> None:
    model = BeltModel.build(PAPER_BASELINE.with_(sigma=0.5), "consistent")
    t = np.linspace(0.0, t_end, 4001)
    t_exact, seg_exact = cpu(lambda: ExactSwitchSolver().segments(model, t_end), repeats)
    ref = cycle_quantities(record_from_segments(seg_exact))
    x_ref, v_ref, _ = sample_segments(seg_exact, t)
    print(
        f"Affine baseline (sigma = 0.5, {t_end:g} s): switch solver vs exact, CPU ratio to exact in this run"
    )
    print(f"{'method':>24} {'cycle err':>10} {'traj err':>10} {'CPU [s]':>9} {'ratio':>7} {'RHS':>7}")
    print(f"{'exact':>24} {'0':>10} {'0':>10} {t_exact:9.4f} {1.0:7.1f} {'-':>7}")
    for rtol in (1e-6, 1e-9, 1e-12):
        solver = SwitchSolver(rtol=rtol, atol=rtol / 10)
        stats = SolverStats()
        elapsed, seg = cpu(lambda s=solver: s.segments(model, t_end), repeats)
        solver.segments(model, t_end, stats)
        q = cycle_quantities(record_from_segments(seg))
        x, v, _ = sample_segments(seg, t)
        cycle_err = max(abs(q[k] - ref[k]) for k in ref)
        traj_err = max(np.max(np.abs(x - x_ref)), np.max(np.abs(v - v_ref)))
        label = f"switch rtol={rtol:g}"
        ratio = elapsed / t_exact
        rhs = stats.rhs_evaluations
        print(f"{label:>24} {cycle_err:10.1e} {traj_err:10.1e} {elapsed:9.4f} {ratio:7.1f} {rhs:7d}")


def law_table(repeats: int) -> None:
    section = yaml.safe_load((ROOT / "config" / "validation.yaml").read_text())["validation"]
    job = PeerJob.model_validate(PeerJob.part_of(section))
    solver, t_end, peer = switch_solver(job.solver, "validation.solver"), job.t_end, job.peer
    print(f"\nEvery law of config/validation.yaml ({t_end:g} s): switch solver and CVODE peer")
    print(
        f"{'law':>10} {'switch CPU [s]':>14} {'phases':>7} {'RHS':>8} {'CVODE CPU [s]':>14} {'CVODE RHS':>10}"
    )
    for name in job.laws:
        try:
            model = law_model(job, name)
        except (OSError, ValueError) as exc:  # the Fig. 17 table is a pipeline output
            print(f"{name:>10} skipped: {exc}")
            continue
        stats = SolverStats()
        elapsed, seg = cpu(lambda m=model: solver.segments(m, t_end), repeats)
        solver.segments(model, t_end, stats)
        peer_cpu, (_, counters) = cpu(lambda m=model: peer_events(m, t_end, peer), repeats)
        print(
            f"{name:>10} {elapsed:14.4f} {len(seg):7d} {stats.rhs_evaluations:8d} {peer_cpu:14.4f}"
            f" {counters['rhs_evaluations']:10d}"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one repeat instead of three")
    args = parser.parse_args()
    repeats = 1 if args.quick else 3
    affine_table(repeats)
    law_table(repeats)


if __name__ == "__main__":
    main()
