"""The compiled kernels (one per contact law) reproduce the reference Python loop step for step."""

import numpy as np
import pytest

from stickslip.fe.explicit import integrate
from stickslip.fe.params import FrictionTable, SceneParams
from stickslip.fe.scene import build_scene

FIG17 = FrictionTable.paper_fig17()

CASES = {
    # every branch: stick, slip, separation (30 deg, fast disc lifts the tip), penalty, prescribed force
    "kinematic_stick_slip": ({"method": "kinematic"}, 0.5, "static"),
    "kinematic_30deg_drop": ({"method": "kinematic", "angle_deg": 30.0}, 19.9, "drop"),
    "penalty_drop": ({"method": "penalty", "penalty_stiffness": 1000.0}, 19.9, "drop"),
    "fixed_normal": ({"method": "fixed_normal"}, 0.5, "static"),
}


def _scene(contact, speed, n=8):
    m = {"beam": {"n_elements": n}, "disc": {"surface_speed_mm_s": speed}, "contact": contact}
    return build_scene(SceneParams.from_mapping(m), FIG17)


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("beta", [0.0, 5e-9])
def test_compiled_matches_python_loop(case, beta):
    contact, speed, start = CASES[case]
    s = _scene(contact, speed)
    kw = dict(output_interval=2e-6, initial_state=start, stiffness_damping=beta, record_state=True)
    a = integrate(s.system, s.law, 0.02, backend="compiled", **kw)
    b = integrate(s.system, s.law, 0.02, backend="python", **kw)
    assert a.n_steps == b.n_steps > 1000
    assert a.step_counts == b.step_counts
    np.testing.assert_array_equal(a.state, b.state)
    # round-off relative to each group's scale (a component that is itself round-off, e.g. y at 0 deg,
    # is compared against the group's scale, not its own)
    groups = (("x", "y"), ("vx", "vy", "slip_velocity"), ("normal_force", "friction_force"))
    for group in groups:
        scale = max(np.abs(getattr(b, name)).max() for name in group)
        assert scale > 0
        for name in group:
            got, ref = getattr(a, name), getattr(b, name)
            np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9 * scale, err_msg=name)
    np.testing.assert_allclose(a.q_samples, b.q_samples, rtol=0, atol=1e-9 * np.abs(b.q_samples).max())


def test_kernel_exercises_all_states():
    # guard for the agreement test above: the cases together visit stick, slip and separation
    seen = set()
    for contact, speed, start in CASES.values():
        s = _scene(contact, speed)
        r = integrate(s.system, s.law, 0.02, output_interval=2e-6, initial_state=start)
        seen |= {k for k, v in r.step_counts.items() if v > 0}
    assert seen == {"stick", "slip", "separation"}


def test_divergence_is_flagged_and_stops():
    s = _scene({"method": "kinematic"}, 0.5)
    r = integrate(s.system, s.law, 0.01, dt=3.0 * integrate(s.system, s.law, 1e-6).dt_crit, blowup=1.0)
    assert r.extra["diverged"] and r.t[-1] < 0.01


def test_unknown_backend_is_rejected():
    s = _scene({"method": "kinematic"}, 0.5)
    with pytest.raises(ValueError, match="backend"):
        integrate(s.system, s.law, 1e-4, backend="fortran")


@pytest.mark.parametrize("case", list(CASES))
def test_recording_chosen_dofs_equals_the_full_recording(case):
    contact, speed, start = CASES[case]
    s = _scene(contact, speed)
    kw = dict(safety_factor=0.9, output_interval=1e-5, initial_state=start, record_state=True)
    full = integrate(s.system, s.law, 2e-3, **kw)
    dofs = np.array([s.system.n - 1, 1, 4])
    some = integrate(s.system, s.law, 2e-3, record_dofs=dofs, **kw)
    assert some.q_samples.shape == (full.q_samples.shape[0], 3)
    np.testing.assert_array_equal(some.q_samples, full.q_samples[:, dofs])
    np.testing.assert_array_equal(some.v_samples, full.v_samples[:, dofs])
