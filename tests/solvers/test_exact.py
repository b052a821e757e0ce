"""Exact switch solver: closed-form limit cycles and every hard case as an explicit scene."""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from stickslip.analysis.errors import segment_cycle_metrics
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import STICK, ExactSwitchSolver, SolverError
from stickslip.solvers.exact import Segment, first_exit_root
from stickslip.solvers.linear import LinearSegment


def scene(variant="consistent", **changes):
    return BeltModel.build(PAPER_BASELINE.with_(**changes), variant)


def closed_form_cycle(p):
    """Independent closed form of the consistent-law limit cycle on a constant belt.

    Stick ends at x_r = (mu N - C V)/K with v = V; slip (backward) solves
    M x'' + (C - mu N sigma) x' + K x = mu N (1 - sigma V) from (x_r, V); it ends at the first
    return v = V; stick then carries the mass back to x_r at speed V.
    """
    mun, V = p.mu_s * p.normal_force, p.belt_velocity
    c = p.damping - mun * p.sigma
    xr = (mun - p.damping * V) / p.stiffness
    p0 = mun * (1 - p.sigma * V) / p.stiffness
    alpha = -c / (2 * p.mass)
    w = math.sqrt(p.stiffness / p.mass - alpha**2)
    A = xr - p0
    B = (V - alpha * A) / w

    def x(t):
        return p0 + math.exp(alpha * t) * (A * math.cos(w * t) + B * math.sin(w * t))

    def v(t):
        return math.exp(alpha * t) * (
            (alpha * A + w * B) * math.cos(w * t) + (alpha * B - w * A) * math.sin(w * t)
        )

    if A == 0.0:  # zero slip damping and release at the equilibrium: a harmonic orbit grazing v = V
        return 2 * math.pi / w, 2 * V / w
    grid = np.linspace(1e-3, 4 * math.pi / w, 4001)
    g = np.array([v(t) - V for t in grid])
    k = np.nonzero((g[:-1] < 0) & (g[1:] >= 0))[0][0]
    t_slip = brentq(lambda t: v(t) - V, grid[k], grid[k + 1], xtol=1e-15, rtol=4e-15)
    vz = np.array([v(t) for t in grid])
    zeros = [
        brentq(v, grid[i], grid[i + 1], xtol=1e-15, rtol=4e-15)
        for i in np.nonzero(np.sign(vz[:-1]) != np.sign(vz[1:]))[0]
        if grid[i + 1] <= t_slip
    ]
    xs = x(t_slip)
    return t_slip + (xr - xs) / V, x(zeros[0]) - x(zeros[1])


# Stick-slip cycles of the consistent law. (mu_s = 0.8 or C = 0.1 with sigma = 0.5 are not here: the
# unbounded linear fall of the friction makes those orbits grow without bound, so they have no cycle.)
@pytest.mark.parametrize(
    "changes",
    [
        dict(sigma=0.5),
        dict(sigma=0.3),
        dict(sigma=0.4),
        dict(sigma=0.5, belt_velocity=1.0),
        dict(sigma=0.5, belt_velocity=0.3),
        dict(sigma=0.5, damping=2.0),
        dict(sigma=0.5, mu_s=0.6),
    ],
)
def test_limit_cycle_matches_closed_form(changes):
    model = scene(**changes)
    period, amplitude = closed_form_cycle(model.params)
    got = segment_cycle_metrics(ExactSwitchSolver().segments(model, 60.0))
    assert got["period"] == pytest.approx(period, rel=1e-9, abs=0)
    assert got["amplitude"] == pytest.approx(amplitude, rel=1e-9, abs=0)


def test_baseline_stick_and_slip_lengths(baseline05):
    segs = [s for s in ExactSwitchSolver().segments(baseline05, 40.0) if s.t1 > s.t0]
    stick = [s.t1 - s.t0 for s in segs[1:-1] if s.phase == STICK]
    slip = [s.t1 - s.t0 for s in segs[1:-1] if s.phase != STICK]
    assert np.allclose(stick[-3:], 1.3776, atol=1e-4) and np.allclose(slip[-3:], 2.2096, atol=1e-4)


def test_release_exactly_at_boundary_with_zero_acceleration(baseline05):
    """Scene: the mass starts sticking exactly at the release position, D = |a| at t = 0."""
    xr = baseline05.stick_release_position()
    model = scene(sigma=0.5, x0=xr)
    assert float(model.stick_demand(0.0, xr)) == pytest.approx(abs(model.friction.a), rel=1e-15)
    segs = ExactSwitchSolver().segments(model, 5.0)
    first = [s for s in segs if s.t1 > s.t0][0]
    assert first.phase != STICK and first.t0 == 0.0  # slips at once, no stick of positive length
    assert float(first.motion.acceleration(0.0)) == pytest.approx(0.0, abs=1e-12)
    assert first.t1 - first.t0 == pytest.approx(2.2096, abs=1e-4)


def test_zero_slip_damping_grazes_every_period(baseline03):
    """Scene sigma = 0.3: sigma mu_s N = C, so slip is undamped and returns tangentially to v = V_b."""
    assert baseline03.slip_damping() == 0.0
    segs = ExactSwitchSolver().segments(baseline03, 40.0)
    slips = [s for s in segs if s.phase != STICK and s.t1 > s.t0][:-1]  # the last one is cut at t_end
    assert len(slips) == 13
    w = math.sqrt(5.0)
    for s in slips:
        assert s.t1 - s.t0 == pytest.approx(2 * math.pi / w, rel=1e-12)
        x1, v1 = s.state(s.t1)
        assert float(v1) == pytest.approx(0.5, abs=1e-12)  # grazing return to the belt velocity
        assert float(s.motion.acceleration(s.t1 - s.t0)) == pytest.approx(0.0, abs=1e-9)
    # between slips the mass only touches the belt: sticks last at most a rounding-level instant
    assert all(s.t1 - s.t0 <= 1e-12 for s in segs[1:] if s.phase == STICK)


def test_grazing_is_not_missed_at_coarse_sampling(baseline03):
    segs = ExactSwitchSolver(samples_per_period=4).segments(baseline03, 20.0)
    slips = [s for s in segs if s.phase != STICK and s.t1 > s.t0][:-1]
    assert len(slips) == 6
    assert all(s.t1 - s.t0 == pytest.approx(2 * math.pi / math.sqrt(5), rel=1e-12) for s in slips)


def test_decelerating_belt_reaches_zero_speed():
    """Scene Section 6: V_b = 0.5 - 0.025 t, belt at rest from t = 20 s."""
    model = scene(sigma=0.5, belt_deceleration=0.025)
    solver = ExactSwitchSolver()
    segs = solver.segments(model, 40.0)
    assert any(s.t1 == pytest.approx(20.0, abs=1e-12) for s in segs)
    after = [s for s in segs if s.t0 >= 20.0]
    assert after and all(s.phase == STICK for s in after)
    tr = solver.solve(model, 40.0, np.linspace(0, 40, 4001))
    assert tr.ok
    late = tr.t > 20.0
    assert np.all(tr.v[late] == 0.0) and np.ptp(tr.x[late]) == 0.0
    assert abs(tr.x[-1]) * model.params.stiffness <= abs(model.friction.a)  # held by static friction


def test_belt_stops_during_slip_is_a_scheduled_event():
    model = scene(sigma=0.5, belt_deceleration=0.5 / 2.5)  # stops at 2.5 s, inside the first slip
    segs = ExactSwitchSolver().segments(model, 10.0)
    assert any(s.t1 == pytest.approx(2.5, abs=1e-12) for s in segs)
    _check_continuity(segs)


@pytest.mark.parametrize("variant", ["eq3_printed", "eq4_printed"])
def test_printed_variants_never_stick(variant):
    model = scene(variant, sigma=0.5)
    tr = ExactSwitchSolver().solve(model, 40.0, np.linspace(0, 40, 2001))
    assert tr.ok
    assert not np.any(tr.segments[:, 2] == STICK)
    assert np.all(np.isfinite(tr.x))


def test_zero_length_loop_raises_clear_error(baseline05):
    class Stuck(ExactSwitchSolver):
        def _slip(self, model, t0, x0, v0, s, t_limit):
            return Segment(t0, t0, s, LinearSegment(1, 1, 1, 0, 0, x0, v0)), True

    solver = Stuck(max_zero_length=10)
    model = scene(sigma=0.5, x0=baseline05.stick_release_position())
    with pytest.raises(SolverError, match="zero-length"):
        solver.segments(model, 5.0)
    tr = solver.solve(model, 5.0)
    assert tr.stats.status == "failed" and "zero-length" in tr.stats.message


def test_segment_limit_raises(baseline05):
    with pytest.raises(SolverError, match="segments"):
        ExactSwitchSolver(max_segments=3).segments(baseline05, 40.0)


@pytest.mark.parametrize("t_end", [0.0, -1.0, float("nan"), float("inf"), "x"])
def test_bad_t_end_is_an_error(baseline05, t_end):
    with pytest.raises(SolverError, match="t_end"):
        ExactSwitchSolver().solve(baseline05, t_end)


def test_first_exit_root_cases():
    assert first_exit_root(-1.0, 1.0, 0.0) == pytest.approx(1.0)
    assert first_exit_root(0.0, 1.0, 0.0) == 0.0  # on the boundary and leaving: exit now
    assert first_exit_root(0.0, -1.0, 0.0) == math.inf
    assert first_exit_root(-1.0, 0.0, 1.0) == pytest.approx(1.0)
    assert first_exit_root(-1.0, 0.0, -1.0) == math.inf
    assert first_exit_root(0.0, 0.0, 1.0) == 0.0


OMEGA_BASELINE = math.sqrt(5.0)


def _check_continuity(segs, omega=OMEGA_BASELINE):
    """x and v agree at every switch to rounding of the state's own scale (orbits may grow large)."""
    for a, b in zip(segs[:-1], segs[1:]):
        assert a.t1 == b.t0
        xa, va = (float(q) for q in a.state(a.t1))
        xb, vb = (float(q) for q in b.state(b.t0))
        vscale = max(1.0, abs(va), omega * abs(xa))
        assert xb == pytest.approx(xa, rel=1e-12, abs=1e-12)
        assert vb == pytest.approx(va, rel=0, abs=1e-9 * vscale)


params_strategy = st.fixed_dictionaries(
    {
        "sigma": st.floats(0.0, 0.6),
        "damping": st.floats(0.0, 3.0),
        "mu_s": st.floats(0.2, 1.0),
        "belt_velocity": st.floats(0.1, 1.5),
        "x0": st.floats(-1.0, 1.0),
        "v0": st.floats(-1.0, 1.5),
        "belt_deceleration": st.sampled_from([0.0, 0.0, 0.025, 0.2]),
    }
)
hyp = settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@hyp
@given(params_strategy)
def test_property_continuous_at_every_switch(changes):
    model = scene(**changes)
    segs = ExactSwitchSolver().segments(model, 15.0)
    _check_continuity(segs, math.sqrt(model.params.stiffness / model.mass))


@hyp
@given(params_strategy)
def test_property_stick_demand_within_static_limit(changes):
    model = scene(**changes)
    a = abs(model.friction.a)
    for s in ExactSwitchSolver().segments(model, 15.0):
        if s.phase != STICK or s.t1 <= s.t0:
            continue
        # half-open [t0, t1): at a belt stop the demand jumps by M d at t1 itself (the belt's
        # deceleration vanishes), which is exactly what ends the stick there
        t = s.t0 + (s.t1 - s.t0) * np.array([0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1 - 1e-9])
        x, v = s.state(t)
        assert np.all(np.abs(model.stick_demand(t, x)) <= a * (1 + 1e-9) + 1e-12)
        assert np.allclose(v, model.belt_velocity(t), rtol=0, atol=1e-12)


@hyp
@given(params_strategy)
def test_property_energy_balance_over_slip(changes):
    """E = M v^2/2 + K x^2/2 changes by the work of friction and damping over every slip segment."""
    from scipy.integrate import quad

    model = scene(**changes)
    p = model.params
    for s in ExactSwitchSolver().segments(model, 8.0)[:6]:
        if s.phase == STICK or s.t1 - s.t0 < 1e-6:
            continue

        def power(t, s=s):
            x, v = (float(q) for q in s.state(t))
            vb = float(model.belt_velocity(t))
            force = model.friction.a * s.phase + model.friction.b * v + model.friction.kappa * vb
            return v * (force - p.damping * v)

        def energy(t, s=s):
            x, v = (float(q) for q in s.state(t))
            return 0.5 * model.mass * v * v + 0.5 * p.stiffness * x * x

        work, _ = quad(power, s.t0, s.t1, epsabs=1e-12, epsrel=1e-11, limit=200)
        scale = max(abs(energy(s.t0)), abs(energy(s.t1)), 1e-3)
        assert energy(s.t1) - energy(s.t0) == pytest.approx(work, abs=1e-8 * scale)


@pytest.mark.parametrize(
    "changes",
    [
        dict(units="si"),  # hundreds of short slips
        dict(units="si", damping=0.5),  # one slip lasting 38 s (thousands of oscillations, growing)
        dict(units="si", belt_deceleration=0.02),
        dict(belt_deceleration=0.025),
    ],
)
def test_growing_scan_windows_find_the_same_events(changes, monkeypatch):
    """Scanning a long slip in doubling windows (same sample spacing) finds exactly the events that
    fixed 256-sample windows find: every segment's start and end agree bit for bit."""
    import stickslip.solvers.exact as exact

    model = scene(**changes)
    with np.errstate(all="ignore"):
        growing = ExactSwitchSolver().segments(model, 40.0)
        monkeypatch.setattr(exact, "WINDOW_SAMPLES", (256, 256))
        fixed = ExactSwitchSolver().segments(model, 40.0)
    assert len(growing) == len(fixed) > 1
    assert [(s.t0, s.t1, s.phase) for s in growing] == [(s.t0, s.t1, s.phase) for s in fixed]
