"""The closed-form slip segment against its ODE, for every damping regime."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from stickslip.solvers.linear import LinearSegment

#: Segments of every damping kind (c from slightly negative to heavily overdamped), any forcing and start.
SEGMENTS = dict(
    m=st.floats(0.1, 5),
    c=st.floats(-2, 20),
    k=st.floats(0.5, 20),
    g0=st.floats(-5, 5),
    g1=st.floats(-1, 1),
    x0=st.floats(-2, 2),
    v0=st.floats(-2, 2),
)


def reference(seg, tau):
    def rhs(t, y):
        return [y[1], (seg.g0 + seg.g1 * t - seg.c * y[1] - seg.k * y[0]) / seg.m]

    sol = solve_ivp(rhs, (0, tau[-1]), [seg.x0, seg.v0], t_eval=tau, rtol=1e-12, atol=1e-13, method="DOP853")
    return sol.y


@pytest.mark.parametrize("c", [0.0, -1.0, 1.5, 2 * np.sqrt(5.0), 2 * np.sqrt(5.0) * (1 + 1e-9), 12.0])
def test_matches_a_tight_numerical_solution(c):
    seg = LinearSegment(m=1.0, c=c, k=5.0, g0=3.75, g1=-0.1, x0=0.85, v0=0.5)
    tau = np.linspace(0, 4, 81)
    x, v = seg.state(tau)
    xr, vr = reference(seg, tau)
    scale = max(1.0, np.abs(xr).max())
    assert np.max(np.abs(x - xr)) < 1e-9 * scale
    assert np.max(np.abs(v - vr)) < 1e-8 * max(1.0, np.abs(vr).max())


def test_undamped_case_is_the_harmonic_closed_form():
    w = np.sqrt(5.0)
    seg = LinearSegment(m=1.0, c=0.0, k=5.0, g0=4.25, g1=0.0, x0=0.85, v0=0.5)
    tau = np.linspace(0, 10, 101)
    x, v = seg.state(tau)
    np.testing.assert_allclose(x, 0.85 + 0.5 / w * np.sin(w * tau), atol=1e-14)
    np.testing.assert_allclose(v, 0.5 * np.cos(w * tau), atol=1e-14)


@settings(max_examples=60, deadline=None)
@given(
    **SEGMENTS,
)
def test_initial_state_and_residual(m, c, k, g0, g1, x0, v0):
    seg = LinearSegment(m=m, c=c, k=k, g0=g0, g1=g1, x0=x0, v0=v0)
    x, v = seg.state(0.0)
    assert x == pytest.approx(x0, abs=1e-12) and v == pytest.approx(v0, abs=1e-12)
    # the ODE residual, with the derivative of v from central differences
    tau, h = 0.37, 1e-5
    _, vp = seg.state(tau + h)
    _, vm = seg.state(tau - h)
    xt, vt = seg.state(tau)
    accel = (vp - vm) / (2 * h)
    residual = m * accel + c * vt + k * xt - (g0 + g1 * tau)
    scale = abs(g0) + abs(g1) + abs(k * xt) + abs(c * vt) + abs(m * accel) + 1
    assert abs(residual) < 1e-5 * scale


@settings(max_examples=80, deadline=None)
@given(
    **SEGMENTS,
    lo=st.floats(0.0, 3.0),
    width=st.floats(0.01, 2.0),
)
# Found by hypothesis: heavily overdamped (c/m = 155), where the test's own curvature carried 1.9e-8 of
# rounding (the bound itself agrees with a 60-digit evaluation to 1e-13).
@example(m=0.109375, c=17.0, k=0.5, g0=0.0, g1=1.0, x0=1.0, v0=1.0, lo=2.5, width=1.0)
def test_velocity_curvature_bound_holds_on_the_interval(m, c, k, g0, g1, x0, v0, lo, width):
    """The bound the exact solver's event search relies on: |v''| never exceeds it on [lo, lo + width]."""
    seg = LinearSegment(m=m, c=c, k=k, g0=g0, g1=g1, x0=x0, v0=v0)
    hi = lo + width
    tau = np.linspace(lo, hi, 201)
    x, v = seg.state(tau)
    # v'' = d/dtau of the ODE's acceleration (g1 - c v' - k v) / m, with v' the acceleration itself
    accel = (g0 + g1 * tau - c * v - k * x) / m
    curvature = (g1 - c * accel - k * v) / m
    # Rounding of that estimate: its own cancelling terms, and v's, whose error it amplifies by (c/m)^2 + k/m
    # (v sums terms of the size below, which cancel when the damping is heavy).
    ec, es = seg._kernels(tau)
    h0, h1 = seg._h
    q = h1 - seg._alpha * h0
    v_terms = np.abs(seg._alpha * (h0 * ec + q * es)) + np.abs(seg._w2 * h0 * es) + np.abs(q * ec)
    v_rounding = 16 * np.finfo(float).eps * np.max(v_terms)
    rounding = 1e-9 * np.max(abs(g1) + np.abs(c * accel) + np.abs(k * v)) / m + v_rounding * (
        (c / m) ** 2 + k / m
    )
    bound = float(seg.velocity_curvature_bound(lo, hi))
    assert np.max(np.abs(curvature)) <= bound + rounding + 1e-12


def test_velocity_curvature_bound_is_zero_at_rest_and_tight_for_a_pure_oscillation():
    at_rest = LinearSegment(m=1.0, c=3.0, k=1.0, g0=2.0, g1=0.0, x0=2.0, v0=0.0)  # overdamped, at equilibrium
    assert float(at_rest.velocity_curvature_bound(0.0, 5.0)) == 0.0
    harmonic = LinearSegment(m=1.0, c=0.0, k=4.0, g0=0.0, g1=0.0, x0=0.0, v0=1.0)  # v = cos 2t, |v''| <= 4
    assert float(harmonic.velocity_curvature_bound(0.0, 10.0)) == pytest.approx(4.0, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(**SEGMENTS, tau=st.floats(0.0, 5.0))
def test_a_scalar_time_gives_the_bits_of_the_array_form(m, c, k, g0, g1, x0, v0, tau):
    """state() keeps a scalar time a Python float (the root searches' fast path): same bits as an array."""
    seg = LinearSegment(m=m, c=c, k=k, g0=g0, g1=g1, x0=x0, v0=v0)
    x, v = seg.state(tau)
    xs, vs = seg.state(np.array([tau, 0.5 * tau]))
    np.testing.assert_array_equal([x, v], [xs[0], vs[0]])
