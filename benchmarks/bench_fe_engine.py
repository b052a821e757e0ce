"""CPU per simulated second of the explicit engine, this tree against a reference commit, in one run.

Runs (simulated window in ``CASES``): the full 20-element beam (default reading: lower-face kinematic
contact, drop start, beta 5e-9 s) at 15.2 rev/min (``section9_kinematic_15p2rpm``) and at 0.5 mm/s
(``section9_kinematic_0p5mm_s``) for 0.1 s, its Craig-Bampton reduction for 0.5 s, and the continuum strip
100 x 1 on the 15.2 rev/min scene for 0.01 s. Each measurement runs in a fresh child process (the
reference tree is the package at ``--ref`` extracted with ``git archive``), the two trees alternate, and the
minimum of ``--repeat`` process-CPU times of the integration loop (``ExplicitResult.cpu_time``,
``time.process_time``) is kept: the machine is shared, the minimum is the least disturbed run.

Usage: PYTHONPATH=src python benchmarks/bench_fe_engine.py [--ref a610954] [--repeat 5] [--scale 1]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# (label, kind, scene, simulated seconds, extra) measured by the child
CASES = (
    ("beam full, 15.2 rev/min", "beam", "section9_kinematic_15p2rpm", 0.1, {}),
    ("beam full, 0.5 mm/s", "beam", "section9_kinematic_0p5mm_s", 0.1, {}),
    ("beam CB reduced, 15.2 rev/min", "beam", "section9_kinematic_15p2rpm", 0.5, {"reduced": True}),
    ("continuum 100x1, 15.2 rev/min", "continuum", "section9_kinematic_15p2rpm", 0.01, {}),
)

CHILD = r"""
import json, sys, yaml
from stickslip.fe.params import FrictionTable
from stickslip.fe.scene import SceneParams, build_scene
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import scene_mapping
cases, scale = json.loads(sys.argv[1])
cfg = yaml.safe_load(open("config/fe.yaml"))["fe"]
FE = Fe.model_validate(cfg)  # the typed section: scenes resolve over its defaults and readings
fr = FrictionTable.paper_fig17()
out = {}
for label, kind, name, window, extra in cases:
    window *= scale
    m = scene_mapping(FE, name)
    if kind == "beam":
        from stickslip.fe.explicit import integrate
        from stickslip.fe.reduced import contact_boundary, craig_bampton
        p = SceneParams.from_mapping({k: m[k] for k in ("beam", "disc", "contact", "solver")})
        sc = build_scene(p, fr)
        system, sf = sc.system, p.solver.safety_factor
        if extra.get("reduced"):
            red = cfg["reduced"]
            mask = (sc.beam.free % 3) == 0
            system, _ = craig_bampton(system, contact_boundary(system), red["n_bending_modes"], mask,
                                      red["n_axial_modes"])
            sf = red["safety_factor"]
        kw = dict(safety_factor=sf, output_interval=p.solver.output_dt, initial_state=p.solver.initial_state,
                  stiffness_damping=p.solver.stiffness_damping)
        integrate(system, sc.law, 1e-4, **kw)  # compile or load the cache outside the timing
        r = integrate(system, sc.law, window, **kw)
    else:
        from stickslip.fe.continuum import integrate_continuum
        from stickslip.studies.fe_continuum import continuum_scene_from_mapping
        cs = continuum_scene_from_mapping(m, fr, 100, 1)
        integrate_continuum(cs, 1e-5)
        r = integrate_continuum(cs, window, output_interval=2.5e-6, initial_state="drop")
    out[label] = (r.cpu_time, float(r.t[-1]), r.n_steps)
print(json.dumps(out))
"""


def extract(ref: str, into: Path) -> Path:
    """The package tree of commit ``ref`` (``src/`` only), for a child process's PYTHONPATH."""
    archive = into / "ref.tar"
    subprocess.run(["git", "archive", "-o", str(archive), ref, "src"], cwd=ROOT, check=True)
    with tarfile.open(archive) as tar:
        tar.extractall(into, filter="data")
    return into / "src"


def measure(src: Path, scale: float) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src))
    payload = json.dumps([CASES, scale])
    done = subprocess.run(
        [sys.executable, "-c", CHILD, payload], cwd=ROOT, env=env, check=True, capture_output=True, text=True
    )
    return json.loads(done.stdout)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ref", default="a610954", help="reference commit (the per-law loops)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--scale", type=float, default=1.0, help="multiplies every run's simulated window")
    a = ap.parse_args()
    best = {"ref": {}, "new": {}}
    with tempfile.TemporaryDirectory() as tmp:
        trees = {"ref": extract(a.ref, Path(tmp)), "new": ROOT / "src"}
        for _ in range(a.repeat):
            for which, src in trees.items():  # alternate, so that load from others hits both alike
                for label, (cpu, t_end, steps) in measure(src, a.scale).items():
                    prev = best[which].get(label)
                    if prev is None or cpu < prev[0]:
                        best[which][label] = (cpu, t_end, steps)
    head = f"{'run':32s} {'steps':>8s} {'ref CPU/s_sim':>14s} {'new CPU/s_sim':>14s} {'new/ref':>8s}"
    print(f"reference {a.ref} vs this tree, minimum of {a.repeat} runs each (process CPU of the loop)")
    print(head)
    print("-" * len(head))
    for label, *_ in CASES:
        (c0, t0, n0), (c1, t1, n1) = best["ref"][label], best["new"][label]
        assert n0 == n1, f"{label}: the two trees ran different step counts ({n0} vs {n1})"
        print(f"{label:32s} {n1:8d} {c0 / t0:14.3f} {c1 / t1:14.3f} {c1 / t1 / (c0 / t0):8.3f}")


if __name__ == "__main__":
    main()
