"""Bit-for-bit regression of the explicit engine: every output array of a set of short runs (beam full and
Craig-Bampton reduced model, each contact law, drop and static start, recorded states, a diverging run;
continuum kinematic and penalty) hashed and compared with the digests stored in ``engine_digests.json``.

The digests were written by the per-law compiled loops that the one engine replaced, so a refactoring of
the engine that changes any bit of any result fails here. The inputs (system matrices, start state, time
step) come from LAPACK/ARPACK, whose last bits may differ on another CPU; each case therefore also stores a
digest of its inputs, and a case whose inputs differ on this machine is skipped rather than failed.

Regenerate (only when a result is meant to change): ``PYTHONPATH=src python tests/fe/test_engine_digests.py``
"""

from __future__ import annotations

import ast
import hashlib
import json
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from stickslip.fe.continuum import build_continuum, integrate_continuum
from stickslip.fe.continuum import stable_time_step as continuum_stable_time_step
from stickslip.fe.continuum import static_state as continuum_static_state
from stickslip.fe.explicit import integrate, stable_time_step, static_state
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable
from stickslip.fe.reduced import contact_boundary, craig_bampton
from stickslip.fe.scene import SceneParams, build_scene
from stickslip.studies.fe import scene_mapping

ROOT = Path(__file__).resolve().parents[2]
DIGESTS = Path(__file__).with_name("engine_digests.json")
FIG17 = FrictionTable.paper_fig17()
STICKY = FrictionTable((0.0, 0.6), (1e4, 0.9e4))  # friction far above what the strip can pull: it sticks
STEPS = 3000  # a few thousand steps: past the drop's first contact, with stick, slip and separation
SERIES = ("t", "x", "y", "vx", "vy", "normal_force", "friction_force", "slip_velocity", "state")


def digest(*arrays) -> str:
    h = hashlib.sha256()
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(str((a.dtype.str, a.shape)).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:24]


def result_digests(r) -> dict:
    """One digest per output array, plus the scalars and counters of the run."""
    d = {name: digest(getattr(r, name)) for name in SERIES}
    for name in ("q_samples", "v_samples"):
        if getattr(r, name) is not None:
            d[name] = digest(getattr(r, name))
    d["scalars"] = repr((r.dt, r.n_steps, r.step_counts, r.extra.get("second_half_counts")))
    d["diverged"] = bool(r.extra["diverged"])
    return d


# ------------------------------------------------------------------------------------------------ beam
def beam_system(scene_name: str, reduced: bool):
    fe = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]
    m = scene_mapping(fe, scene_name)
    p = SceneParams.from_mapping({k: m[k] for k in ("beam", "disc", "contact", "solver")})
    scene = build_scene(p, FIG17)
    system = scene.system
    if reduced:  # as stickslip.studies.fe.run_scene does
        red = fe["reduced"]
        mask = (scene.beam.free % 3) == 0
        boundary = contact_boundary(system)
        system, _ = craig_bampton(system, boundary, red["n_bending_modes"], mask, red["n_axial_modes"])
    return system, scene.law, p.solver


def run_beam(
    scene_name, start, reduced=False, record=False, beta=None, alpha=0.0, dt_factor=None, steps=STEPS
):
    system, law, solver = beam_system(scene_name, reduced)
    beta = solver.stiffness_damping if beta is None else beta
    sf = 0.5 if reduced else 0.9
    dt = (dt_factor or sf) * stable_time_step(system, law)
    inputs = digest(system.M, system.K, system.f, system.c_n, system.c_t, static_state(system, law)[0], [dt])
    r = integrate(
        system, law, steps * dt * (1 - 1e-9), dt=dt, output_interval=solver.output_dt, initial_state=start,
        mass_damping=alpha, stiffness_damping=beta, record_state=record,
        record_dofs=np.array([system.n - 1, 1, 4]) if record and not reduced else None,
        blowup=1.0 if dt_factor else 1e6, chunk=700,
    )  # fmt: skip
    return inputs, r


BEAM_CASES = {
    f"beam_{model}_{scene}_{start}": (scene, start, model == "reduced")
    for model in ("full", "reduced")
    for scene in ("section9_kinematic_15p2rpm", "section11_penalty_15p2rpm", "section10_fixed_normal_0p5mm_s")
    for start in ("drop", "static")
}
BEAM_EXTRA = {
    "beam_full_kinematic_30deg_drop_recorded": dict(scene_name="section12_angle30_15p2rpm", start="drop",
                                                     record=True),
    "beam_reduced_penalty_static_recorded": dict(scene_name="section11_penalty_0p5mm_s", start="static",
                                                 reduced=True, record=True),
    "beam_full_kinematic_mass_damping_only": dict(scene_name="section9_kinematic_0p5mm_s", start="drop",
                                                  beta=0.0, alpha=2000.0),
    "beam_full_kinematic_diverging": dict(scene_name="section9_kinematic_0p5mm_s", start="static",
                                          dt_factor=3.0),
    "beam_full_kinematic_0p5mm_s_static_long": dict(scene_name="section9_kinematic_0p5mm_s", start="static",
                                                    steps=40_000),
}  # fmt: skip


# ------------------------------------------------------------------------------------------- continuum
def run_continuum(
    method,
    start,
    angle=0.0,
    record=False,
    dt_factor=None,
    speed=None,
    steps=STEPS,
    sticky=False,
    rotation="clockwise",
):
    contact = ContactParams(method=method, penalty_stiffness=1000.0, angle_deg=angle)
    disc = DiscParams(speed_rev_per_min=15.2) if speed is None else DiscParams(surface_speed_mm_s=speed)
    friction = STICKY if sticky else FIG17
    s = build_continuum(
        BeamParams(), disc, contact, friction, nx=100, ny=1, damping_beta=5e-9, disc_rotation=rotation
    )
    dt = (dt_factor or 0.9) * continuum_stable_time_step(s)
    inputs = digest(s.K.data, s.mass, s.f, s.gap0, continuum_static_state(s)[0], [dt])
    n = steps if not record else 300
    r = integrate_continuum(
        s, n * dt * (1 - 1e-9), dt=dt, output_interval=2.5e-6, initial_state=start, record_state=record,
        blowup=1.0 if dt_factor else 1e3, chunk=700,
    )  # fmt: skip
    return inputs, r


CONTINUUM_CASES = {
    "continuum_kinematic_drop": dict(method="kinematic", start="drop"),
    "continuum_kinematic_static": dict(method="kinematic", start="static"),
    "continuum_penalty_drop": dict(method="penalty", start="drop"),
    "continuum_penalty_static": dict(method="penalty", start="static"),
    "continuum_kinematic_30deg_drop": dict(method="kinematic", start="drop", angle=30.0),
    "continuum_kinematic_recorded": dict(method="kinematic", start="drop", record=True),
    "continuum_penalty_diverging": dict(method="penalty", start="static", dt_factor=2.5),
    "continuum_kinematic_0p5mm_s_static_long": dict(
        method="kinematic", start="static", speed=0.5, steps=40_000
    ),
    "continuum_kinematic_sticking": dict(
        method="kinematic", start="static", speed=0.5, sticky=True, rotation="counterclockwise"
    ),
    "continuum_penalty_sticking_lifts_off": dict(
        method="penalty", start="static", speed=0.5, sticky=True, steps=20_000
    ),
}


def run_case(name):
    if name in BEAM_CASES:
        scene_name, start, reduced = BEAM_CASES[name]
        return run_beam(scene_name, start, reduced)
    if name in BEAM_EXTRA:
        return run_beam(**BEAM_EXTRA[name])
    return run_continuum(**CONTINUUM_CASES[name])


CASES = [*BEAM_CASES, *BEAM_EXTRA, *CONTINUUM_CASES]


@pytest.mark.parametrize("name", CASES)
def test_every_output_array_is_bit_identical_to_the_stored_digest(name):
    stored = json.loads(DIGESTS.read_text())[name]
    inputs, r = run_case(name)
    if inputs != stored["inputs"]:
        pytest.skip("the run's inputs (LAPACK/ARPACK results) differ in their last bits on this machine")
    assert result_digests(r) == stored["outputs"]


def test_the_cases_cover_every_contact_state_and_the_diverged_flag():
    stored = json.loads(DIGESTS.read_text())
    assert set(stored) == set(CASES)
    seen = set()
    for d in stored.values():
        counts = ast.literal_eval(d["outputs"]["scalars"])[2]
        seen |= {k for k, v in counts.items() if v > 0}
    assert seen == {"stick", "slip", "separation"}
    assert any(d["outputs"]["diverged"] for d in stored.values())
    assert any("q_samples" in d["outputs"] for d in stored.values())


if __name__ == "__main__":  # regenerate the stored digests
    table = {}
    for name in CASES:
        inputs, r = run_case(name)
        table[name] = {"inputs": inputs, "outputs": result_digests(r)}
        print(name, r.n_steps, r.step_counts, r.extra["diverged"], file=sys.stderr)
    DIGESTS.write_text(json.dumps(table, indent=1, sort_keys=True) + "\n")
