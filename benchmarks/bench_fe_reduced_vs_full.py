"""Reduced (Craig-Bampton) vs full explicit FE beam-on-disc model, measured in the same run.

Usage: python benchmarks/bench_fe_reduced_vs_full.py [duration_s]   (default 0.2 s simulated per run)
"""

import sys

from stickslip.fe.params import FrictionTable
from stickslip.studies.fe_scene import run_scene

DUR = float(sys.argv[1]) if len(sys.argv) > 1 else 0.2
BASE = {
    "beam": {"n_elements": 20},
    "disc": {"diameter": 25.0},
    "contact": {},
    "solver": {"output_dt": 1e-5},
}
CASES = {
    "s9 0.5 mm/s (stick-slip)": {"disc": {"diameter": 25.0, "surface_speed_mm_s": 0.5}},
    "s9 15.2 rpm (slip)": {"disc": {"diameter": 25.0, "speed_rev_per_min": 15.2}},
    "s12 30deg 15.2 rpm": {
        "disc": {"diameter": 25.0, "speed_rev_per_min": 15.2},
        "contact": {"angle_deg": 30.0},
    },
}
MODELS = {
    "full FE (20 el, 60 dof)": None,
    "CB 4 bend+1 ax, sf 0.9": {"n_bending_modes": 4, "n_axial_modes": 1, "safety_factor": 0.9},
    "CB 4 bend+1 ax, sf 0.5": {"n_bending_modes": 4, "n_axial_modes": 1, "safety_factor": 0.5},
    "CB 8 bend+2 ax, sf 0.5": {"n_bending_modes": 8, "n_axial_modes": 2, "safety_factor": 0.5},
}
fr = FrictionTable.paper_fig17()
hdr = (
    f"{'case':26s} {'model':24s} {'f_dom[Hz]':>10s} {'ampl[mm]':>10s} {'stick':>6s} {'slip':>6s} {'sep':>6s} "
    f"{'dt[s]':>9s} {'CPU[s]':>7s} {'CPU/full':>8s} {'df/f':>7s} {'dA/A':>7s}"
)
print(f"simulated time per run: {DUR} s")
print(hdr)
print("-" * len(hdr))
for cname, case in CASES.items():
    ref = None
    for mname, red in MODELS.items():
        mp = {**BASE, **case}
        _, m, _ = run_scene(mp, fr, duration=DUR, reduced=red)
        if ref is None:
            ref = m
        df = (
            m["dominant_frequency"] / ref["dominant_frequency"] - 1
            if ref["dominant_frequency"]
            else float("nan")
        )
        da = (
            m["horizontal_amplitude"] / ref["horizontal_amplitude"] - 1
            if ref["horizontal_amplitude"]
            else float("nan")
        )
        print(
            f"{cname:26s} {mname:24s} {m['dominant_frequency']:10.1f} {m['horizontal_amplitude']:10.3e} "
            f"{m['stick_fraction']:6.3f} {m['slip_fraction']:6.3f} {m['separation_fraction']:6.3f} "
            f"{m['time_step']:9.2e} "
            f"{m['cpu_time']:7.2f} {m['cpu_time'] / ref['cpu_time']:8.3f} {df:+7.3f} {da:+7.3f}"
        )
