"""Cost of the inverse study in the default build: CPU seconds per stage, measured in one run.

Target: the whole study (fits, sampling, identifiability profiles, conflict search, misprint scans, datasets
and corner plots) within 90 s of CPU, so the clean build keeps its 4 min budget. `--long` measures the long
run (config `inverse.long: true`) instead.

`--conflict-check` measures instead how much the minimal conflicting subsets depend on the optimiser's
budget: each inconsistent figure's search is repeated with 10, 20 and 40 least-squares iterations per subset
(fresh forward models, so no run is reused) and the sets are compared; exit 1 if they differ.

usage: PYTHONPATH=src python benchmarks/bench_inverse.py [--long] [--out DIR] [--conflict-check]
"""

import argparse
import glob
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml

from stickslip.inverse.conflicts import minimal_conflicts
from stickslip.inverse.forward import Forward
from stickslip.inverse.outputs import write_study
from stickslip.inverse.problem import build_problem, load_claim_rows
from stickslip.inverse.study import fit_problem, run_study
from stickslip.schema import InverseJob, InverseOnedof

ROOT = Path(__file__).resolve().parents[1]
BUDGET = 90.0


def conflict_check(job: InverseJob, claims) -> int:
    """Minimal conflicting subsets with 10, 20 and 40 iterations per subset fit: identical or not."""
    settings = job.inverse.mode_settings
    differ = 0
    print(f"{'figure / family':28s} {'sets (nfev 10, 20, 40)':>24s} {'CPU [s]':>22s}  identical")
    for name in job.inverse.figures:
        for fam in job.inverse.families:
            p = build_problem(job, claims, name, fam)
            r = fit_problem(p, settings, settings.steps, conflicts=False)
            if r.fit.consistent:
                continue
            seeds = [r.fit.free_values, p.stated_free]
            seeds += list(r.region.samples_free) if r.region is not None else []
            sets, cpu = [], []
            for nfev in (10, 20, 40):
                t0 = time.process_time()
                search = minimal_conflicts(Forward(p), seeds, max_nfev=nfev)
                cpu.append(time.process_time() - t0)
                sets.append(sorted(c.members for c in search.conflicts) + [search.witness is not None])
            same = sets[0] == sets[1] == sets[2]
            differ += not same
            counts = ", ".join(str(len(s) - 1) for s in sets)
            print(f"{name + ' / ' + fam:28s} {counts:>24s} {', '.join(f'{c:.2f}' for c in cpu):>22s}  {same}")
    print("identical for every figure" if not differ else f"{differ} figure(s) differ")
    return int(differ > 0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--long", action="store_true")
    ap.add_argument("--out", default=None)
    ap.add_argument("--conflict-check", action="store_true")
    args = ap.parse_args()
    sections = {}
    for name in ("config.yaml", "inverse.yaml"):
        sections.update(yaml.safe_load((ROOT / "config" / name).read_text()))
    sections["inverse"]["long"] = bool(args.long)
    onedof = InverseOnedof.part_of(sections["onedof"])
    job = InverseJob.model_validate({"onedof": onedof, "inverse": sections["inverse"]})
    claims = load_claim_rows(sorted(glob.glob(str(ROOT / "config" / "claims" / "*.yaml"))))
    if args.conflict_check:
        return conflict_check(job, claims)

    # cost of one forward evaluation (all runs of a problem), the unit everything else is made of
    rows = []
    for name, fam in (
        ("fig02", "consistent"),
        ("fig02", "plateau"),
        ("joint", "consistent"),
        ("joint", "plateau"),
    ):
        p = build_problem(job, claims, name, fam)
        fw = Forward(p)
        t0 = time.process_time()
        for k in range(5):
            fw.measure(p.stated_free * (1 + 1e-3 * (k + 1)))
        rows.append((f"one evaluation: {name}/{fam} ({len(p.runs)} runs)", (time.process_time() - t0) / 5))

    t0 = time.process_time()
    out = run_study(job, claims)
    study = time.process_time() - t0
    t1 = time.process_time()
    target = Path(args.out) if args.out else Path(tempfile.mkdtemp(prefix="bench_inverse_"))
    write_study(out, target)
    writing = time.process_time() - t1
    rows += [(f"fit {name} (both families)", cpu) for name, cpu in out["cpu"].items()]
    rows += [
        ("study (fits, sampling, scans)", study),
        ("datasets + corner plots", writing),
        ("whole study", study + writing),
    ]
    mode = "long" if args.long else "default"
    print(f"inverse study, {mode} mode (process CPU seconds; budget {BUDGET:g} s for the default build)")
    print(f"{'stage':58s} {'CPU [s]':>10s} {'/ budget':>9s}")
    for label, cpu in rows:
        print(f"{label:58s} {cpu:10.3f} {cpu / BUDGET:9.3f}")
    total = study + writing
    print(
        f"{'within budget' if total <= BUDGET else 'OVER BUDGET'}: {total:.1f} s of {BUDGET:g} s"
        f" ({mode} mode; outputs in {target})"
    )
    return 0 if (args.long or total <= BUDGET) else 1


if __name__ == "__main__":
    np.seterr(all="ignore")
    raise SystemExit(main())
