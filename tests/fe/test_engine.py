"""The one explicit engine: every model's wrapper runs :func:`stickslip.fe.engine.run_steps`, with the
structure, contact and recorder pieces its data selects, and the compiled engine reproduces the reference
Python loop step for step on the full beam and its Craig-Bampton reduction, for each contact law."""

import numpy as np
import pytest

from stickslip.fe import continuum, driver, engine, explicit
from stickslip.fe.continuum import build_continuum, integrate_continuum
from stickslip.fe.explicit import integrate, integrate_python
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable, SceneParams
from stickslip.fe.reduced import contact_boundary, craig_bampton
from stickslip.fe.scene import build_scene

FIG17 = FrictionTable.paper_fig17()
SERIES = ("t", "x", "y", "vx", "vy", "normal_force", "friction_force", "slip_velocity")
LAWS = {  # contact mapping, disc speed [mm/s], start: together they visit stick, slip and separation
    "kinematic": ({"method": "kinematic", "angle_deg": 30.0}, 19.9, "drop"),
    "penalty": ({"method": "penalty", "penalty_stiffness": 1000.0}, 19.9, "drop"),
    "fixed_normal": ({"method": "fixed_normal"}, 0.5, "static"),
}


def beam(law, reduced=False, n=8):
    contact, speed, start = LAWS[law]
    m = {"beam": {"n_elements": n}, "disc": {"surface_speed_mm_s": speed}, "contact": contact}
    s = build_scene(SceneParams.from_mapping(m), FIG17)
    system = s.system
    if reduced:
        system, _ = craig_bampton(system, contact_boundary(system), 4, (s.beam.free % 3) == 0, 1)
    return system, s.law, start


def strip(method):
    contact = ContactParams(method=method, penalty_stiffness=1000.0)
    return build_continuum(BeamParams(), DiscParams(surface_speed_mm_s=19.9), contact, FIG17, nx=40, ny=1)


@pytest.mark.parametrize("reduced", [False, True], ids=["full", "reduced"])
@pytest.mark.parametrize("law", list(LAWS))
def test_engine_matches_the_python_loop_at_every_step(law, reduced):
    system, contact_law, start = beam(law, reduced)
    dt = 0.9 * explicit.stable_time_step(system, contact_law)
    kw = dict(dt=dt, initial_state=start, stiffness_damping=5e-9, record_state=True)  # a sample per step
    a = integrate(system, contact_law, 2500 * dt, **kw)
    b = integrate_python(system, contact_law, 2500 * dt, **kw)
    assert a.n_steps == b.n_steps == a.t.size - 1 == 2500
    assert a.step_counts == b.step_counts
    np.testing.assert_array_equal(a.state, b.state)
    np.testing.assert_array_equal(a.t, b.t)
    for name in SERIES[1:]:
        ref = getattr(b, name)
        scale = max(np.abs(ref).max(), 1e-300)
        np.testing.assert_allclose(getattr(a, name), ref, rtol=0, atol=1e-9 * scale, err_msg=name)
    for name in ("q_samples", "v_samples"):
        ref = getattr(b, name)
        np.testing.assert_allclose(getattr(a, name), ref, rtol=0, atol=1e-9 * np.abs(ref).max(), err_msg=name)


def test_the_beam_laws_together_visit_every_contact_state():
    # guard for the step-for-step test above
    seen = set()
    for law in LAWS:
        system, contact_law, start = beam(law, reduced=True)
        dt = 0.9 * explicit.stable_time_step(system, contact_law)
        r = integrate(system, contact_law, 2500 * dt, dt=dt, initial_state=start, stiffness_damping=5e-9)
        seen |= {k for k, v in r.step_counts.items() if v > 0}
    assert seen == {"stick", "slip", "separation"}


@pytest.mark.parametrize("reduced", [False, True], ids=["full", "reduced"])
@pytest.mark.parametrize("law", list(LAWS))
def test_the_band_and_csr_structures_give_the_same_bits(law, reduced, monkeypatch):
    system, contact_law, start = beam(law, reduced, n=20)
    dt = 0.9 * explicit.stable_time_step(system, contact_law)
    kw = dict(dt=dt, initial_state=start, stiffness_damping=5e-9, output_interval=3 * dt, record_state=True)
    runs = {}
    for make in (explicit.csr_structure, explicit.band_structure):
        monkeypatch.setattr(explicit, "beam_structure", make)
        runs[make.__name__] = integrate(system, contact_law, 3000 * dt, **kw)
    a, b = runs.values()
    assert a.step_counts == b.step_counts and a.n_steps == b.n_steps > 1000
    for name in (*SERIES, "state", "q_samples", "v_samples"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_the_beam_takes_the_band_structure_and_a_small_dense_model_csr():
    for reduced, expected in ((False, engine.BandStructure), (True, engine.CsrStructure)):
        system, contact_law, start = beam("kinematic", reduced, n=20)
        pr = explicit._prepare(system, contact_law, 1e-4, None, 0.9, None, start, None, None, 0.0, 0.0)
        assert isinstance(explicit.beam_structure(pr, 0.0), expected)


def spy_on_the_engine(monkeypatch, module=None):
    """Record the piece types of every engine call a wrapper makes (through the one driver, ``module``)."""
    module = module or driver
    calls = []

    def spy(*args):
        calls.append(tuple(type(a).__name__ for a in args[-3:]))
        return engine.run_steps(*args)

    monkeypatch.setattr(module, "run_steps", spy)
    return calls


@pytest.mark.parametrize("law", list(LAWS))
def test_the_beam_wrapper_runs_the_engine_with_the_laws_pieces(law, monkeypatch):
    calls = spy_on_the_engine(monkeypatch)
    system, contact_law, start = beam(law)
    integrate(system, contact_law, 2e-4, initial_state=start, chunk=500)
    piece = {"kinematic": "KinematicPoint", "penalty": "PenaltyPoint", "fixed_normal": "FixedNormalPoint"}
    assert len(calls) > 1 and len(set(calls)) == 1
    structure, contact, recorder = calls[0]
    assert structure in ("CsrStructure", "BandStructure") and (contact, recorder) == (
        piece[law],
        "PointRecorder",
    )


@pytest.mark.parametrize("method", ["kinematic", "penalty"])
def test_the_continuum_wrapper_runs_the_engine_with_the_laws_pieces(method, monkeypatch):
    calls = spy_on_the_engine(monkeypatch)
    integrate_continuum(strip(method), 1e-4, chunk=200)
    assert len(calls) > 1 and set(calls) == {("QuadStructure", "SlaveNodes", "NodeRecorder")}
    kp = continuum.node_contact(strip(method), 1e-7).kp  # the method is the piece's penalty stiffness
    assert (kp > 0) == (method == "penalty")


@pytest.mark.parametrize("law", list(LAWS))
def test_the_engine_called_directly_gives_the_beam_wrappers_result(law):
    system, contact_law, start = beam(law)
    wrapped = integrate(system, contact_law, 5e-4, initial_state=start, stiffness_damping=5e-9)
    pr = explicit._prepare(system, contact_law, 5e-4, None, 0.9, None, start, None, None, 0.0, 5e-9)
    out, st = np.zeros((8, pr.n_out)), np.zeros(pr.n_out, np.int8)
    explicit._record0(pr, system, contact_law, out, st, None, None)
    none = np.zeros((1, 1))
    recorder = explicit.point_recorder(system, contact_law, out, st, False, none, none, np.arange(system.n))
    structure, contact = explicit.csr_structure(pr, 5e-9), explicit.point_contact(system, contact_law, pr)
    counts = np.zeros(3, np.int64)
    u, v = pr.u.copy(), pr.v.copy()
    j, n, diverged = engine.run_steps(
        1, pr.n_steps, pr.every, 1, pr.dt, 1e6, u, v, counts, structure, contact, recorder
    )
    assert (n, diverged) == (wrapped.n_steps, False)
    assert driver.named_counts(counts) == wrapped.step_counts
    np.testing.assert_array_equal(st[:j], wrapped.state)
    for k, name in enumerate(SERIES):
        np.testing.assert_array_equal(out[k, :j], getattr(wrapped, name), err_msg=name)


@pytest.mark.parametrize("method", ["kinematic", "penalty"])
def test_the_engine_called_directly_gives_the_continuum_wrappers_result(method):
    s = strip(method)
    dt = 0.9 * continuum.stable_time_step(s)
    wrapped = integrate_continuum(s, 2000 * dt, dt=dt)
    n_out = wrapped.t.size
    out, st = np.zeros((n_out, 8)), np.zeros(n_out, np.int8)
    out[0], st[0] = [getattr(wrapped, name)[0] for name in SERIES], wrapped.state[0]
    u, v = np.zeros(s.mesh.n_dof), np.zeros(s.mesh.n_dof)
    counts = np.zeros(3, np.int64)
    pieces = (
        continuum.quad_structure(s, dt),
        continuum.node_contact(s, dt),
        continuum.node_recorder(s, out, st),
    )
    j, n, diverged = engine.run_steps(1, wrapped.n_steps, 1, 1, dt, 1e3, u, v, counts, *pieces)
    assert (j, n, diverged) == (n_out, 2000, False)
    assert dict(zip(("separation", "stick", "slip"), counts.tolist())) == wrapped.step_counts
    np.testing.assert_array_equal(st, wrapped.state)
    for k, name in enumerate(SERIES):
        np.testing.assert_array_equal(out[:, k], getattr(wrapped, name), err_msg=name)


def test_a_piece_of_unknown_type_is_a_typing_error():
    from numba.core.errors import TypingError

    s = strip("kinematic")
    pieces = (
        continuum.quad_structure(s, 1e-8),
        ("not", "a", "contact"),
        continuum.node_recorder(s, np.zeros((2, 8)), np.zeros(2, np.int8)),
    )
    u = np.zeros(s.mesh.n_dof)
    with pytest.raises(TypingError):
        engine.run_steps(1, 1, 1, 1, 1e-8, 1e3, u, u.copy(), np.zeros(3, np.int64), *pieces)
