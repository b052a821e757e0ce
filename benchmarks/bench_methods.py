"""Speed vs accuracy of the integration methods on the paper's 40 s baseline (issue 3).

Prints: method, settings, state error, period and amplitude errors (relative, vs the exact solver), CPU time
(min over repeats, process time), RHS evaluations, and the CPU ratio to the paper's method
(sign() + RK45, rtol 1e-3, atol 1e-6: MATLAB ode45 defaults) measured in the same run.

    .venv/bin/python benchmarks/bench_methods.py [--sigma 0.5] [--quick]
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from stickslip.analysis.errors import measure_run, segment_cycle_metrics
from stickslip.analysis.failure import classify
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import make_solver

PAPER = ("sign_rk", {"method": "RK45", "rtol": 1e-3, "atol": 1e-6})


def method_grid(quick: bool):
    rtols = (1e-2, 1e-3, 1e-4) if quick else (1e-2, 1e-3, 1e-4, 1e-5)
    grid = [("exact", {})]
    grid += [
        ("sign_rk", {"method": m, "rtol": r, "atol": r * 1e-3}) for m in ("RK45", "DOP853") for r in rtols
    ]
    for eps in (1e-2, 1e-4) if quick else (1e-2, 1e-3, 1e-4, 1e-5):
        grid.append(
            ("smooth", {"regularization": "tanh", "eps": eps, "method": "Radau", "rtol": 1e-6, "atol": 1e-9})
        )
    grid += [
        ("smooth", {"regularization": "arctan", "eps": 1e-4, "method": m, "rtol": 1e-6, "atol": 1e-9})
        for m in ("BDF", "LSODA")
    ]
    grid += [("karnopp", {"eta": e, "rtol": 1e-6, "atol": 1e-9}) for e in (1e-2, 1e-3, 1e-4)]
    grid += [
        ("moreau", {"h": h, "theta": th})
        for th in (0.5, 1.0)
        for h in ((1e-2, 1e-3) if quick else (1e-2, 3e-3, 1e-3, 1e-4))
    ]
    return grid


def fmt(x, spec=".2e"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sigma", type=float, default=0.5)
    ap.add_argument("--t-end", type=float, default=40.0)
    ap.add_argument("--quick", action="store_true", help="fewer settings (CI)")
    ap.add_argument(
        "--max-rhs", type=int, default=250_000, help="stall budget per adaptive run [RHS evaluations]"
    )
    args = ap.parse_args(argv)

    model = BeltModel.build(PAPER_BASELINE.with_(sigma=args.sigma), "consistent")
    t_eval = np.linspace(0.0, args.t_end, int(round(args.t_end * 100)) + 1)
    exact = make_solver("exact")
    ref = exact.solve(model, args.t_end, t_eval)
    ref_cycle = segment_cycle_metrics(exact.segments(model, args.t_end))
    budget = dict(max_rhs=args.max_rhs, max_cpu=60.0)  # as config/methods.yaml: a count, the same anywhere

    rows = []
    _, paper = measure_run(
        make_solver(PAPER[0], **PAPER[1]), model, args.t_end, t_eval, ref, ref_cycle, **budget
    )
    for name, settings in method_grid(args.quick):
        traj, rec = measure_run(
            make_solver(name, **settings), model, args.t_end, t_eval, ref, ref_cycle, **budget
        )
        rec["failure"] = classify(traj, ref, model.params)["failure_kind"]
        rows.append((name, settings, rec))

    print(
        f"# scene: baseline consistent sigma={args.sigma}, {args.t_end:g} s; reference period "
        f"{ref_cycle['period']:.12g} s, peak-to-peak {ref_cycle['amplitude']:.12g} mm"
    )
    print(
        f"# paper's method {PAPER[0]} {PAPER[1]}: {paper['cpu_time'] * 1e3:.1f} ms CPU, "
        f"{paper['rhs_evaluations']} RHS evals (min of {paper['repeats']})"
    )
    head = (
        f"{'method':8s} {'settings':44s} {'state_err':>9s} {'period_err':>10s} {'ampl_err':>9s} "
        f"{'cpu_ms':>9s} {'rhs_evals':>9s} {'cpu/paper':>9s} {'status':7s} failure"
    )
    print(head)
    print("-" * len(head))
    for name, settings, r in rows:
        s = ",".join(
            f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}" for k, v in settings.items() if k != "atol"
        )
        ratio = r["cpu_time"] / paper["cpu_time"]
        print(
            f"{name:8s} {s[:44]:44s} {fmt(r['state']):>9s} {fmt(r['period_error']):>10s} "
            f"{fmt(r['amplitude_error']):>9s} {r['cpu_time'] * 1e3:9.3f} {r['rhs_evaluations']:9d} "
            f"{ratio:9.4f} {r['status']:7s} {r['failure']}"
        )
    ex = next(r for n, _, r in rows if n == "exact")
    print(
        f"\nexact solver speed-up over the paper's method on the {args.t_end:g} s baseline: "
        f"{paper['cpu_time'] / ex['cpu_time']:.0f}x ({paper['cpu_time'] * 1e3:.1f} ms / "
        f"{ex['cpu_time'] * 1e3:.3f} ms, same run; issue target >= 100x)"
    )
    print(
        "\nPareto front of the approximate methods (CPU time vs state error, successful runs; "
        "the exact solver is faster and exact):"
    )
    ok = sorted(
        (r["cpu_time"], r["state"], n, st) for n, st, r in rows if r["status"] == "ok" and n != "exact"
    )
    best = math.inf
    for cpu, err, n, st in ok:
        if err < best:
            best = err
            print(f"  {cpu * 1e3:9.3f} ms  state_err {err:.2e}  {n} {st}")


if __name__ == "__main__":
    main()
