"""Continuum strip (QM6 plane stress) on the rigid disc: element (patch test, bending), natural frequencies
against the cantilever closed forms, the explicit stability limit, energy conservation, kinematic and penalty
contact laws, and mesh convergence of the drop-start response."""

import dataclasses
import math

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.fe.beam import cantilever_axial_frequencies, cantilever_bending_frequencies
from stickslip.fe.continuum import (
    assemble_strip,
    build_continuum,
    increments,
    integrate_continuum,
    natural_frequencies,
    omega_max_elementwise,
    omega_max_global,
    plane_stress_matrix,
    quad_stiffness,
    stable_time_step,
    static_state,
    strip_mesh,
)
from stickslip.fe.engine import friction_coefficient
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable

BEAM = BeamParams()
FIG17 = FrictionTable.paper_fig17()


def scene(nx=100, ny=1, speed=0.5, friction=FIG17, disc_rotation="clockwise", **kw):
    contact = ContactParams(**kw.pop("contact", {}))
    disc = DiscParams(surface_speed_mm_s=speed, direction=disc_rotation)
    return build_continuum(BEAM, disc, contact, friction, nx=nx, ny=ny, **kw)


def without_contact(s):
    e = np.zeros(0, np.int64)
    return dataclasses.replace(s, contact_nodes=e, normals=np.zeros((0, 2)), tangents=np.zeros((0, 2)),
                               gap0=np.zeros(0), primary=-1)  # fmt: skip


# ------------------------------------------------------------------------------------------- element
@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.floats(-1.0, 1.0), min_size=6, max_size=6),
    st.floats(-0.25, 0.25),
    st.floats(-0.25, 0.25),
)
def test_patch_test_distorted_mesh_reproduces_linear_field(coef, dx, dy):
    # 2x2 patch on [0,2]^2 with the centre node moved: a linear displacement field imposed on the boundary
    # must be reproduced exactly inside (QM6's Taylor correction makes this hold on distorted shapes)
    g = np.array([[x, y] for y in (0.0, 1.0, 2.0) for x in (0.0, 1.0, 2.0)])
    g[4] += (dx, dy)
    quads = np.array([[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]])
    D = plane_stress_matrix(210e3, 0.3)
    K = np.zeros((18, 18))
    for q in quads:
        d = np.ravel(np.column_stack([2 * q, 2 * q + 1]))
        K[np.ix_(d, d)] += quad_stiffness(g[q], D, 1.0)
    a = np.asarray(coef)
    u_exact = np.column_stack(
        [a[0] + a[1] * g[:, 0] + a[2] * g[:, 1], a[3] + a[4] * g[:, 0] + a[5] * g[:, 1]]
    )
    u_exact = u_exact.ravel()
    inner = np.array([8, 9])
    bnd = np.setdiff1d(np.arange(18), inner)
    u_in = np.linalg.solve(K[np.ix_(inner, inner)], -K[np.ix_(inner, bnd)] @ u_exact[bnd])
    np.testing.assert_allclose(u_in, u_exact[inner], atol=1e-10 * (1 + np.abs(a).max()))


def test_element_has_exactly_three_rigid_body_modes():
    xy = np.array([[0.0, 0.0], [1.3, 0.1], [1.1, 0.9], [-0.1, 1.2]])
    w = np.linalg.eigvalsh(quad_stiffness(xy, plane_stress_matrix(210e3, 0.3), 1.0))
    assert np.sum(np.abs(w) < 1e-9 * w.max()) == 3 and w.min() > -1e-9 * w.max()


def _tip_deflection(nx, ny, incompatible, P=1.0):
    mesh = strip_mesh(BEAM, nx, ny)
    K, *_ = assemble_strip(mesh, BEAM, incompatible)
    fixed = np.zeros(mesh.n_dof, bool)
    fixed[2 * mesh.clamp] = fixed[2 * mesh.clamp + 1] = True
    f = np.zeros(mesh.n_dof)
    end = np.arange(ny + 1) * (nx + 1) + nx
    f[2 * end + 1] = -P / (ny + 1)
    fr = np.nonzero(~fixed)[0]
    u = np.zeros(mesh.n_dof)
    u[fr] = spla.spsolve(K[fr][:, fr].tocsc(), f[fr])
    return -u[2 * end + 1].mean()


def test_incompatible_modes_bend_like_euler_bernoulli_and_plain_q4_locks():
    exact = 1.0 * BEAM.length**3 / (3 * BEAM.E * BEAM.inertia)
    qm6 = _tip_deflection(100, 1, True)
    q4 = _tip_deflection(100, 1, False)
    assert qm6 == pytest.approx(exact, rel=0.01)
    assert q4 < 0.8 * exact  # shear locking of one plain bilinear element through the thickness
    assert abs(qm6 / exact - 1) < 0.05 * abs(q4 / exact - 1)


# ---------------------------------------------------------------------------------- natural frequencies
def _clamped_modes(s, n=12):
    fr = s.free
    K = s.K[fr][:, fr].tocsc()
    M = sp.diags(s.mass[fr]).tocsc()
    w2, phi = spla.eigsh(K, k=n, M=M, sigma=0.0, which="LM")
    order = np.argsort(w2)
    return np.sqrt(w2[order]) / (2 * np.pi), phi[:, order], fr


@pytest.mark.parametrize("nx,ny", [(100, 1), (200, 2)])
def test_natural_frequencies_match_cantilever_closed_forms(nx, ny):
    s = scene(nx, ny)
    f, phi, fr = _clamped_modes(s, 14)
    is_x = (fr % 2) == 0
    axial = (phi[is_x] ** 2).sum(axis=0) > 0.5 * (phi**2).sum(axis=0)
    bend = f[~axial]
    np.testing.assert_allclose(bend[:3], cantilever_bending_frequencies(BEAM, 3), rtol=0.02)
    assert f[axial][0] == pytest.approx(cantilever_axial_frequencies(BEAM, 1)[0], rel=0.02)


def test_propped_strip_first_mode_is_the_clamped_pinned_beam():
    # contact held at the free-end lower corner: first bending mode of a clamped-pinned beam, beta L = 3.9266
    bl = 3.9266023120
    closed = bl**2 / (2 * np.pi * BEAM.length**2) * np.sqrt(BEAM.E * BEAM.inertia / (BEAM.rho * BEAM.area))
    f = natural_frequencies(scene(100, 1), 3)
    assert f[0] == pytest.approx(closed, rel=0.01)
    free = natural_frequencies(scene(100, 1), 3, contact_held=False)
    assert free[0] == pytest.approx(cantilever_bending_frequencies(BEAM, 1)[0], rel=0.01)


# ------------------------------------------------------------------------------------------ time step
def test_element_bound_is_conservative():
    stiff = {"method": "penalty", "penalty_stiffness": 1e9}  # a spring that sets the step
    for nx, ny, contact in [(100, 1, {}), (40, 2, {}), (40, 1, stiff)]:
        s = scene(nx, ny, contact=contact)
        assert omega_max_elementwise(s) >= omega_max_global(s)
        assert stable_time_step(s, "element") <= stable_time_step(s, "global")


@pytest.mark.parametrize("factor,stable", [(0.99, True), (1.01, False)])
def test_global_step_is_the_true_stability_limit(factor, stable):
    # drop start without contact excites every mode a little; just above 2/omega_max the top mode grows by
    # ~30 % per step, just below it everything stays bounded
    s = without_contact(scene(30, 1))
    dt = factor * stable_time_step(s)
    r = integrate_continuum(s, 3000 * dt, dt=dt, output_interval=dt)
    assert (np.abs(r.y).max() < 1.0 and not r.extra["diverged"]) == stable


def test_damping_shortens_the_stable_step():
    s0 = scene(100, 1)
    s1 = scene(100, 1, damping_beta=5e-9)
    w = omega_max_global(s0)
    xi = 0.5 * 5e-9 * w
    assert stable_time_step(s1) == pytest.approx(stable_time_step(s0) * (math.sqrt(1 + xi**2) - xi))


def test_increment_count_for_the_papers_run():
    s = scene(100, 1)
    dt = stable_time_step(s)
    n = increments(s, 0.65, 1.0)
    assert n == math.ceil(0.65 / dt - 1e-9)
    # the ABAQUS banner's 3 688 747 increments at 0.65 s: same order, checked loosely (not tuned)
    assert abs(n / 3_688_747 - 1) < 0.05


# ------------------------------------------------------------------------------------------ energy
def test_undamped_central_difference_conserves_its_discrete_energy():
    s = without_contact(scene(20, 2))
    dt = 0.9 * stable_time_step(s)
    r = integrate_continuum(s, 400 * dt, dt=dt, output_interval=dt, record_state=True)
    u, v = r.q_samples, r.v_samples
    M = s.mass
    # H = 1/2 v_{n+1/2} M v_{n+1/2} + 1/2 u_n K u_{n+1} - f (u_n + u_{n+1}) / 2 is exactly invariant
    H = np.array([
        0.5 * v[k] @ (M * v[k]) + 0.5 * u[k - 1] @ (s.K @ u[k]) - s.f @ (u[k - 1] + u[k]) / 2
        for k in range(2, len(u))
    ])  # fmt: skip
    scale = 0.5 * max(v[k] @ (M * v[k]) for k in range(len(v)))
    assert scale > 0
    assert np.abs(H - H[0]).max() < 1e-9 * scale


def test_stiffness_damping_gives_the_modal_decay_rate():
    # free vibration in the first axial mode: beta K damping gives it xi = beta omega / 2, so its modal
    # amplitude decays as exp(-xi omega t)
    beta = 2e-7
    s = dataclasses.replace(without_contact(scene(50, 1)), damping_beta=beta, f=np.zeros(102 * 2))
    f, phi, fr = _clamped_modes(s, 14)
    is_x = (fr % 2) == 0
    k = int(np.nonzero((phi[is_x] ** 2).sum(axis=0) > 0.5 * (phi**2).sum(axis=0))[0][0])
    w = 2 * np.pi * f[k]
    mode = np.zeros(s.mesh.n_dof)
    mode[fr] = phi[:, k] / np.abs(phi[:, k]).max()
    dt = 0.9 * stable_time_step(s)
    periods = 12
    r = integrate_continuum(s, periods * 2 * np.pi / w, dt=dt, output_interval=dt, u0=1e-4 * mode,
                            record_state=True)  # fmt: skip
    q = r.q_samples @ (s.mass * mode)
    per = int(round(2 * np.pi / w / dt))
    ratio = np.abs(q[-per:]).max() / np.abs(q[:per]).max()
    xi = 0.5 * beta * w
    expected = math.exp(-xi * w * (len(q) - per) * dt)
    assert expected < 0.7  # the check has teeth: a clearly visible decay
    assert ratio == pytest.approx(expected, rel=0.05)


# ------------------------------------------------------------------------------------------ contact
@pytest.mark.parametrize("angle", [0.0, 30.0])
def test_kinematic_contact_never_penetrates(angle):
    s = scene(50, 1, speed=19.9, contact={"angle_deg": angle})
    r = integrate_continuum(s, 0.003, output_interval=2e-6, record_state=True)
    q = r.q_samples
    d = 2 * s.contact_nodes
    gaps = s.gap0 + q[:, d] * s.normals[:, 0] + q[:, d + 1] * s.normals[:, 1]
    assert gaps.min() >= -1e-12
    assert r.step_counts["stick"] + r.step_counts["slip"] > 0
    assert np.abs(q).max() > 1e-6  # the strip did move


@pytest.mark.parametrize("method", ["kinematic", "penalty"])
def test_stick_has_zero_slip_velocity(method):
    # friction far above what the strip can pull: the contact node must move with the disc exactly
    big = FrictionTable((0.0, 0.6), (1e4, 0.9e4))
    # counter-clockwise: friction compresses the strip and its moment about the axis presses the tip down
    s = scene(50, 1, speed=0.5, friction=big, contact={"method": method, "penalty_stiffness": 1e3},
              output_node="contact", disc_rotation="counterclockwise")  # fmt: skip
    r = integrate_continuum(s, 0.002, output_interval=1e-5, initial_state="static")
    assert r.step_counts["slip"] == 0 and r.step_counts["separation"] == 0
    np.testing.assert_allclose(r.slip_velocity[1:], 0.0, atol=1e-12 * 0.5)
    t = s.tangents[s.primary]
    disp_t = (r.x - r.x[0]) * t[0] + (r.y - r.y[0]) * t[1]
    np.testing.assert_allclose(disp_t[1:], 0.5 * r.t[1:], rtol=1e-6)


def test_sticking_friction_at_the_lower_face_lifts_the_tip_off():
    # clockwise disc: sticking friction stretches the strip; at the lower face (h/2 below the axis) it bends
    # the free end upwards until the contact opens. Counter-clockwise presses the tip on: no separation.
    big = FrictionTable((0.0, 0.6), (1e4, 0.9e4))
    sep = {}
    for rot in ("clockwise", "counterclockwise"):
        s = scene(50, 1, speed=0.5, friction=big, disc_rotation=rot)
        r = integrate_continuum(s, 0.002, output_interval=1e-5, initial_state="static")
        sep[rot] = r.step_counts["separation"]
    assert sep["clockwise"] > 0 and sep["counterclockwise"] == 0


def test_penalty_normal_force_is_stiffness_times_previous_penetration():
    kp = 50.0
    s = scene(50, 1, contact={"method": "penalty", "penalty_stiffness": kp}, output_node="contact")
    dt = 0.9 * stable_time_step(s)
    r = integrate_continuum(s, 300 * dt, dt=dt, output_interval=dt)
    n = s.normals[s.primary]
    g_prev = s.gap0[s.primary] + r.x[:-1] * n[0] + r.y[:-1] * n[1]
    np.testing.assert_allclose(r.normal_force[1:], np.where(g_prev < 0, -kp * g_prev, 0.0), rtol=1e-9,
                               atol=1e-15)  # fmt: skip
    assert (r.normal_force > 0).any()


def test_static_state_carries_the_propped_cantilever_reaction():
    s = scene(100, 1)
    u, N = static_state(s)
    assert N == pytest.approx(3 / 8 * BEAM.weight, rel=0.02)
    c = s.contact_nodes[s.primary]
    assert abs(u[2 * c : 2 * c + 2] @ s.normals[s.primary]) < 1e-14


def test_tilted_contact_away_from_the_free_end_is_rejected():
    with pytest.raises(ValueError, match="angle_deg"):
        scene(50, 1, contact={"angle_deg": 30.0}, contact_position=50.0)
    with pytest.raises(ValueError, match="angle_deg"):  # disc centre under the strip: it cuts the face
        scene(50, 1, contact={"angle_deg": -30.0})
    with pytest.raises(ValueError, match="method"):
        scene(50, 1, contact={"method": "fixed_normal"})
    with pytest.raises(ValueError, match="output_node"):
        scene(50, 1, output_node=10_000)


# -------------------------------------------------------------------------------------- convergence
def test_drop_start_response_converges_in_the_time_step():
    s = scene(100, 1, damping_beta=5e-9)
    r1 = integrate_continuum(s, 0.004, safety_factor=0.9, output_interval=1e-6)
    r2 = integrate_continuum(s, 0.004, safety_factor=0.45, output_interval=1e-6)
    assert r1.x.max() == pytest.approx(r2.x.max(), rel=0.01)
    x1 = np.interp(r2.t, r1.t, r1.x)  # sample times differ with dt (output every round(interval/dt) steps)
    assert np.abs(x1 - r2.x).max() < 0.05 * np.abs(r2.x).max()


def test_drop_start_peak_converges_with_the_mesh():
    # peak horizontal displacement of the free-end lower corner (node 1) after a drop start: the lower face
    # turns with the propped bending mode, whose first overshoot comes after half its period
    peaks = []
    for nx, ny in [(100, 1), (200, 2), (400, 4)]:
        s = scene(nx, ny)
        r = integrate_continuum(s, 0.003, output_interval=2e-6)
        k = int(np.argmax(r.x))
        peaks.append(r.x[k])
        assert r.t[k] == pytest.approx(0.5 / natural_frequencies(s, 1)[0], rel=0.1)
    peaks = np.array(peaks)
    assert peaks.min() > 5e-5  # order 1e-4 mm: h/2 times the propped-cantilever end slope, doubled
    np.testing.assert_allclose(peaks[:2], peaks[2], rtol=0.05)


def test_held_upper_face_and_axis_output_node():
    # Section 10 reading: u_y = 0 on the whole upper face; the strip then cannot bend, node 1 on the axis
    # (even ny) moves only along x, and the contact carries only the weight below the held face
    s = scene(50, 2, speed=0.5, constrain_upper_face=True, output_node="free_end_axis")
    assert s.output_node == 1 * 51 + 50  # row j = 1 of 0..2, column i = 50
    u, N = static_state(s)
    assert np.all(u[2 * s.mesh.upper + 1] == 0.0)
    assert 0 < N < 0.1 * 3 / 8 * BEAM.weight
    r = integrate_continuum(s, 0.002, output_interval=1e-5, initial_state="static", record_state=True)
    assert np.abs(r.q_samples[:, 2 * s.mesh.upper + 1]).max() == 0.0
    assert np.abs(r.x - r.x[0]).max() > 0 and np.abs(r.y - r.y[0]).max() < 1e-3 * np.abs(r.x - r.x[0]).max()


def test_penalty_spring_shortens_the_step_and_progress_reports_the_end():
    soft = scene(40, 1, contact={"method": "penalty", "penalty_stiffness": 1.0})
    stiff = scene(40, 1, contact={"method": "penalty", "penalty_stiffness": 1e9})
    assert stable_time_step(stiff) < 0.5 * stable_time_step(soft)
    calls = []
    r = integrate_continuum(soft, 1e-4, progress=lambda done, total: calls.append((done, total)), chunk=100)
    assert calls[-1] == (r.n_steps, r.n_steps) and len(calls) == math.ceil(r.n_steps / 100)


@pytest.mark.parametrize(
    "call,key",
    [
        (lambda: scene(0, 1), "nx"),
        (lambda: scene(10, 1, damping_beta=-1.0), "damping_beta"),
        (lambda: scene(10, 1, contact_position=0.0), "contact_position"),
        (lambda: scene(10, 1, disc_rotation="up"), "direction"),  # the disc's own, checked by DiscParams
        (lambda: scene(10, 1, output_node="middle"), "output_node"),
        (lambda: integrate_continuum(scene(10, 1), -1.0), "duration"),
        (lambda: integrate_continuum(scene(10, 1), 1e-4, safety_factor=1.5), "safety_factor"),
        (lambda: integrate_continuum(scene(10, 1), 1e-4, initial_state="hot"), "initial_state"),
        (lambda: integrate_continuum(scene(10, 1), 1e-4, output_interval=0.0), "output_interval"),
        (lambda: integrate_continuum(scene(10, 1), 1e-4, u0=np.zeros(3)), "u0"),
        (lambda: stable_time_step(scene(10, 1), "guess"), "method"),
    ],
)
def test_bad_input_names_the_key(call, key):
    with pytest.raises(ValueError, match=f"^{key}"):
        call()


def test_light_stiffness_damping_removes_the_contact_chatter_of_the_undamped_mesh():
    # the falling friction law is negative damping N |mu'| on every mode with tangential motion at the
    # contact, including the mesh's highest ones; undamped, they grow until the contact chatters open
    # (within a millisecond of a static start at 0.5 mm/s); beta = 5e-9 s (xi ~ 2e-4 at 12.9 kHz) stops it
    sep = {}
    for beta in (0.0, 5e-9):
        r = integrate_continuum(
            scene(50, 1, damping_beta=beta), 0.003, output_interval=1e-5, initial_state="static"
        )
        sep[beta] = r.step_counts["separation"]
    assert sep[0.0] > 0 and sep[5e-9] == 0


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(0.01, 5.0), min_size=1, max_size=5),
    st.lists(st.floats(0.0, 1.0), min_size=6, max_size=6),
    st.floats(-10.0, 10.0),
)
def test_compiled_friction_lookup_equals_the_table(steps, mus, speed):
    # the kernel re-implements FrictionTable's interpolation (static limit at 0, flat beyond the end)
    speeds = np.concatenate([[0.0], np.cumsum(steps)])
    table = FrictionTable(tuple(speeds), tuple(mus[: speeds.size]))
    got = friction_coefficient(speed, np.asarray(table.speeds), np.asarray(table.mu))
    assert got == pytest.approx(table(speed), abs=1e-12)


def test_axis_node_of_a_one_element_strip_is_the_mean_of_the_free_end_corners():
    rs = {
        node: integrate_continuum(scene(50, 1, output_node=node), 2e-4, output_interval=1e-5)
        for node in ("free_end_lower", "free_end_upper", "free_end_axis")
    }
    for k in ("x", "y", "vx", "vy"):
        mean = 0.5 * (getattr(rs["free_end_lower"], k) + getattr(rs["free_end_upper"], k))
        scale = max(np.abs(getattr(rs[n], k)).max() for n in ("free_end_lower", "free_end_upper"))
        np.testing.assert_allclose(getattr(rs["free_end_axis"], k), mean, rtol=0, atol=1e-9 * scale)
    assert np.abs(rs["free_end_lower"].x - rs["free_end_upper"].x).max() > 0  # the corners differ


def test_reruns_are_bit_identical():
    a, b = (integrate_continuum(scene(50, 1), 3e-4, output_interval=1e-5) for _ in range(2))
    assert a.dt == b.dt
    for k in ("x", "y", "vx", "vy", "normal_force", "friction_force", "slip_velocity", "state"):
        assert np.array_equal(getattr(a, k), getattr(b, k))


@pytest.mark.parametrize("factor", [1.5, -1.0, 0.0])
def test_both_explicit_integrators_refuse_a_step_factor_outside_0_1_naming_it(factor):
    """A factor above 1 steps past the stability limit; the beam's integrator ran such a step unchecked."""
    from stickslip.fe.explicit import integrate
    from stickslip.fe.params import SceneParams
    from stickslip.fe.scene import build_scene

    with pytest.raises(ValueError, match="^safety_factor: "):
        integrate_continuum(scene(10, 1), 1e-4, safety_factor=factor)
    beam = build_scene(SceneParams.from_mapping({"disc": {"speed_rev_per_min": 15.2}}), FIG17)
    with pytest.raises(ValueError, match="^safety_factor: "):
        integrate(beam.system, beam.law, 1e-4, safety_factor=factor)
