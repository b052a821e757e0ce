"""Beam-on-disc CPU times, all measured in this one run.

* the 1 s beam scene (default config: 20 elements, lower-face kinematic contact, drop start, beta 5e-9)
  with the compiled kernel (target <= 1 s CPU);
* compiled kernel vs the reference Python loop on the same short run (same steps, same answers);
* beam (and its Craig-Bampton reduction) vs the continuum strip 100 x 1 on the same window, per simulated
  second, with node-1 amplitude / frequency next to each.

Usage: python benchmarks/bench_fe_kernel.py [window_s]   (default 0.05 s for the model comparison)
"""

import sys
import time

import numpy as np
import yaml

from stickslip.fe.continuum import integrate_continuum
from stickslip.fe.explicit import integrate
from stickslip.fe.metrics import trajectory_metrics
from stickslip.fe.params import FrictionTable
from stickslip.fe.scene import SceneParams, build_scene
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import deep_merge, scene_mapping
from stickslip.studies.fe_continuum import continuum_scene_from_mapping
from stickslip.studies.fe_scene import run_scene

WINDOW = float(sys.argv[1]) if len(sys.argv) > 1 else 0.05
cfg = yaml.safe_load(open("config/fe.yaml"))["fe"]
FE = Fe.model_validate(cfg)  # the typed section: scenes resolve over its defaults and readings
fr = FrictionTable.paper_fig17()
base = scene_mapping(FE, "section9_kinematic_0p5mm_s")
p = SceneParams.from_mapping({k: base[k] for k in ("beam", "disc", "contact", "solver")})
sc = build_scene(p, fr)
kw = dict(initial_state="drop", stiffness_damping=p.solver.stiffness_damping, output_interval=2.5e-6)
integrate(sc.system, sc.law, 1e-4, **kw)  # compile / load the kernel cache outside the timings

print("== 1 s beam scene (section9_kinematic_0p5mm_s, default reading)")
t0 = time.process_time()
r = integrate(sc.system, sc.law, 1.0, **kw)
total = time.process_time() - t0
print(f"steps {r.n_steps}  dt {r.dt:.3g} s  kernel CPU {r.cpu_time:.3f} s  call CPU {total:.3f} s")

print("\n== compiled kernel vs reference Python loop (same 0.01 s run)")
a = integrate(sc.system, sc.law, 0.01, backend="compiled", **kw)
b = integrate(sc.system, sc.law, 0.01, backend="python", **kw)
dx = np.abs(a.x - b.x).max() / np.abs(b.x).max()
print(f"{'backend':10s} {'steps':>8s} {'CPU [s]':>9s} {'us/step':>8s}")
for name, res in (("compiled", a), ("python", b)):
    print(f"{name:10s} {res.n_steps:8d} {res.cpu_time:9.4f} {1e6 * res.cpu_time / res.n_steps:8.3f}")
print(f"python / compiled = {b.cpu_time / a.cpu_time:.0f} x   max |x difference| / max|x| = {dx:.1e}")

print(f"\n== models on the same {WINDOW} s window, per scene (CPU per simulated second)")
hdr = f"{'scene':32s} {'model':22s} {'CPU/s_sim':>9s} {'vs cont.':>8s} {'ampl [mm]':>10s} {'f_dom [Hz]':>10s}"
hdr += f" {'stick':>6s}"
print(hdr)
print("-" * len(hdr))
for scene in ("section9_kinematic_0p5mm_s", "section11_penalty_15p2rpm", "section12_angle30_15p2rpm"):
    mp = deep_merge(scene_mapping(FE, scene), {"solver": {"t_end": WINDOW}})
    ps = SceneParams.from_mapping({k: mp[k] for k in ("beam", "disc", "contact", "solver")})
    cs = continuum_scene_from_mapping(mp, fr, 100, 1)
    integrate_continuum(cs, 1e-5)  # compile outside the timing
    rc = integrate_continuum(cs, WINDOW, output_interval=2.5e-6, initial_state="drop")
    mc = trajectory_metrics(rc)
    rows = [("continuum 100x1", rc.cpu_time, mc)]
    _, mb, _ = run_scene(mp, fr)
    rows.append(("beam 20 el", mb["cpu_time"], mb))
    red = dict(cfg["reduced"])
    _, mr, _ = run_scene(mp, fr, reduced=red)
    rows.append((f"beam CB {red['n_bending_modes']}b+{red['n_axial_modes']}a", mr["cpu_time"], mr))
    for name, cpu, m in rows:
        print(
            f"{scene:32s} {name:22s} {cpu / WINDOW:9.2f} {rc.cpu_time / cpu:7.1f}x "
            f"{m['horizontal_amplitude']:10.3e} {m['dominant_frequency']:10.1f} {m['stick_fraction']:6.3f}"
        )
