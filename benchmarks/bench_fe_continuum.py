"""Continuum strip (QM6, compiled explicit loop) vs the Python explicit loop on the existing beam, one run.

Scene: Section 9 (kinematic contact, 15.2 rev/min clockwise, drop start, Fig. 17 friction). Per mesh: the
stable step (global omega_max and the element-by-element bound), increments for 0.65 s (safety factor 1,
the number comparable to the ABAQUS banner's 3 688 747, and 0.9 as run), CPU per 1e5 steps, the projected
CPU for 0.65 s, and the per-step CPU ratio to ``fe.explicit.integrate`` on the default 20-element beam.

Usage: python benchmarks/bench_fe_continuum.py [--full] [--convergence]
  --full         also runs the 100x1 strip for 0.65 s
  --convergence  node-1 metrics of a 0.05 s drop start (beta = 5e-9 s, both disc speeds) per mesh and
                 safety factor (time step), with CPU
"""

import sys
import time

import numpy as np

from stickslip.fe.continuum import build_continuum, increments, integrate_continuum, stable_time_step
from stickslip.fe.explicit import integrate
from stickslip.fe.metrics import dominant_frequency
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable, SceneParams
from stickslip.fe.scene import build_scene

ABAQUS_INCREMENTS = 3_688_747  # paper, Fig. 33 banner: "Increment 3688747: Step Time = 0.6500"
DURATION = 0.65
N_STEPS = 100_000
SF = 0.9
MESHES = [(100, 1), (200, 2), (400, 4)]

fr = FrictionTable.paper_fig17()
beam, disc, contact = BeamParams(), DiscParams(speed_rev_per_min=15.2), ContactParams(method="kinematic")

# baseline: the existing Python loop on the default beam scene (same disc speed, kinematic contact)
bs = build_scene(SceneParams(beam, disc, contact, SceneParams.from_mapping({}).solver), fr)
rb = integrate(bs.system, bs.law, 2e-3, safety_factor=SF, initial_state="undeformed", output_interval=1e-5)
py_step = rb.cpu_time / rb.n_steps
print(
    f"baseline fe.explicit.integrate, {beam.n_elements}-element beam: {rb.n_steps} steps, "
    f"{py_step * 1e6:.2f} us/step, dt {rb.dt:.3e} s"
)

hdr = (
    f"{'mesh':>6s} {'dof':>5s} {'dt_crit[s]':>11s} {'dt_elem[s]':>11s} {'incr0.65(sf1)':>13s} "
    f"{'vs ABAQUS':>9s} {'incr0.65(sf.9)':>14s} {'CPU/1e5[s]':>10s} {'CPU0.65[s]':>10s} {'step/python':>11s}"
)
print(hdr)
print("-" * len(hdr))
for nx, ny in MESHES:
    s = build_continuum(beam, disc, contact, fr, nx=nx, ny=ny)
    integrate_continuum(s, 1e-6)  # load the compiled kernel outside the timing
    dt_c = stable_time_step(s)
    n1 = increments(s, DURATION, 1.0)
    n9 = increments(s, DURATION, SF)
    r = integrate_continuum(s, N_STEPS * SF * dt_c * (1 - 1e-9), safety_factor=SF, output_interval=1e-5)
    per = r.cpu_time / r.n_steps
    print(
        f"{nx}x{ny:<2d} {s.mesh.n_dof:5d} {dt_c:11.4e} {stable_time_step(s, 'element'):11.4e} {n1:13d} "
        f"{n1 / ABAQUS_INCREMENTS - 1:+9.4f} {n9:14d} {per * 1e5:10.3f} {per * n9:10.1f} "
        f"{per / py_step:11.4f}"
    )

if "--full" in sys.argv:
    s = build_continuum(beam, disc, contact, fr, nx=100, ny=1)
    t0 = time.time()
    r = integrate_continuum(s, DURATION, safety_factor=SF, output_interval=2e-6)
    print(
        f"full 100x1 run, {DURATION} s: {r.n_steps} increments, CPU {r.cpu_time:.1f} s "
        f"(wall {time.time() - t0:.1f} s), fractions {r.fractions()}"
    )

if "--convergence" in sys.argv:
    print("\nconvergence: drop start, 0.05 s, beta = 5e-9 s, node 1 = free-end lower corner, second half")
    hdr = (
        f"{'V[mm/s]':>7s} {'mesh':>6s} {'sf':>5s} {'x_half_pp[mm]':>13s} {'x_mean[mm]':>11s} "
        f"{'y_half_pp[mm]':>13s} {'f_dom[Hz]':>9s} {'stick':>6s} {'slip':>6s} {'sep':>6s} {'CPU[s]':>7s}"
    )
    print(hdr)
    for speed in (0.5, 19.9):
        d = DiscParams(surface_speed_mm_s=speed)
        for nx, ny, sf in [(100, 1, SF), (100, 1, SF / 2), (200, 2, SF), (200, 2, SF / 2), (400, 4, SF)]:
            s = build_continuum(beam, d, contact, fr, nx=nx, ny=ny, damping_beta=5e-9)
            r = integrate_continuum(s, 0.05, safety_factor=sf, output_interval=2e-6)
            h = r.t >= 0.025
            x, y = r.x[h], r.y[h]
            f = r.fractions()
            fd = dominant_frequency(r.t[h], x)
            print(
                f"{speed:7.1f} {nx:>3d}x{ny:<2d} {sf:5.3f} {0.5 * np.ptp(x):13.4e} {x.mean():11.4e} "
                f"{0.5 * np.ptp(y):13.4e} {fd:9.1f} {f['stick']:6.3f} {f['slip']:6.3f} "
                f"{f['separation']:6.3f} {r.cpu_time:7.1f}"
            )
