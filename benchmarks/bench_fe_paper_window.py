"""The paper's time scale: what a 1 s window of every Section 9-12 scene costs, full beam against the
reduced (Craig-Bampton) model, and whether the reduced model is adequate there.

Per scene (default reading, drop start) and model: CPU per simulated second, node 1's horizontal
amplitude, centre and growth ratio of the running envelope over the window, and the closed-form growth
rate of the propped bending mode from mu'(V) (stickslip.fe.mechanics) with the growth it implies over
the window. The last lines project the FE reading jobs' CPU if every scene ran the paper's window (five
readings, the perturbation ensemble's five members and the step-halving run, as the build runs them).

Usage: python benchmarks/bench_fe_paper_window.py [window_s]   (default 1.0 s)
"""

import math
import sys
import time
from pathlib import Path

import yaml

from stickslip.fe import mechanics as mc
from stickslip.fe.params import BeamParams, DiscParams, FrictionTable
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import deep_merge, scene_mapping
from stickslip.studies.fe_scene import run_scene

WINDOW = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
ROOT = Path(__file__).resolve().parents[1]
cfg = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]
FE = Fe.model_validate(cfg)  # the typed section: scenes resolve over its defaults and readings
table = ROOT / cfg["friction_table"]
friction = FrictionTable.from_csv(table) if table.exists() else FrictionTable.paper_fig17()
b = BeamParams()
q, EI, rho_a = mc.distributed_weight(b.rho, b.area, b.g), b.E * b.inertia, b.rho * b.area
n0 = mc.propped_reaction(q, b.length)
a_tip = mc.propped_mode_tip_slope(rho_a, b.length) * b.thickness / 2
omega = 2 * math.pi * mc.bending_frequencies(EI, rho_a, b.length)[0]
beta = float(cfg["defaults"]["solver"]["stiffness_damping"])
RUNS_PER_SCENE = len(cfg["readings"]) * (5 + 2)  # readings x (ensemble members + a half-step run at 2x cost)

print(f"window {WINDOW:g} s, friction table {table.name if table.exists() else 'Fig. 17 description'}")
head = f"{'scene':34s} {'model':8s} {'cpu/s sim':>9s} {'amplitude':>10s} {'centre':>10s} {'growth':>7s}"
print(head + f" {'closed-form growth':>19s}")
cost = {"full": 0.0, "reduced": 0.0}
for name in cfg["scenes"]:
    mp = deep_merge(scene_mapping(FE, name), {"solver": {"t_end": WINDOW}})
    speed = DiscParams.from_mapping(mp["disc"]).surface_speed
    rate = mc.negative_damping_growth_rate(n0, friction.slope(speed), a_tip, omega, beta)
    for model, reduced in (("full", None), ("reduced", cfg["reduced"])):
        t0 = time.process_time()
        _, m, _ = run_scene(mp, friction, reduced=reduced)
        cpu = (time.process_time() - t0) / WINDOW
        cost[model] += cpu * WINDOW * RUNS_PER_SCENE
        print(
            f"{name:34s} {model:8s} {cpu:9.2f} {m['horizontal_amplitude']:10.4g} "
            f"{m['mean_horizontal_displacement']:10.4g} {m['horizontal_amplitude_growth_ratio']:7.3f} "
            f"{rate:+8.3f} 1/s -> x{math.exp(rate * 0.8 * WINDOW):.3f}",
            flush=True,
        )
for model, c in cost.items():
    print(f"projected FE reading jobs' CPU for {WINDOW:g} s windows, {model} model: {c:.0f} s")
