"""Beam elements against closed-form cantilever values and element-count convergence."""

import numpy as np
import pytest

from stickslip.fe.beam import (
    assemble_beam,
    cantilever_axial_frequencies,
    cantilever_bending_frequencies,
    classify_modes,
    modal_analysis,
)
from stickslip.fe.params import BeamParams, FrictionTable


def _split(p):
    b = assemble_beam(p)
    f, phi = modal_analysis(b.K, b.M)
    ax = classify_modes(phi, b.free)
    return f[~ax], f[ax]


@pytest.mark.parametrize("mass", ["lumped", "consistent"])
def test_cantilever_frequencies_closed_form(mass):
    p = BeamParams(n_elements=20, mass=mass)
    fb, fa = _split(p)
    np.testing.assert_allclose(fb[:3], cantilever_bending_frequencies(p, 3), rtol=0.01)
    np.testing.assert_allclose(fa[:2], cantilever_axial_frequencies(p, 2), rtol=0.01)


def test_first_bending_frequency_value():
    # beta L = 1.8751, steel 100 x 1 mm: f1 = 83.55 Hz (width cancels)
    assert cantilever_bending_frequencies(BeamParams(), 1)[0] == pytest.approx(83.55, rel=1e-3)
    assert cantilever_bending_frequencies(BeamParams(width=5.0), 1)[0] == pytest.approx(83.55, rel=1e-3)


@pytest.mark.parametrize("mass", ["lumped", "consistent"])
def test_element_count_convergence(mass):
    errs = []
    for n in (4, 8, 16, 32):
        p = BeamParams(n_elements=n, mass=mass)
        fb, fa = _split(p)
        errs.append(
            max(
                abs(fb[2] / cantilever_bending_frequencies(p, 3)[2] - 1),
                abs(fa[0] / cantilever_axial_frequencies(p, 1)[0] - 1),
            )
        )
    assert all(b < a for a, b in zip(errs, errs[1:])), errs
    assert errs[-1] < 5e-3  # lumped mass converges O(h^2), consistent O(h^4)


def test_gravity_load_total_weight():
    p = BeamParams()
    b = assemble_beam(p)
    v = (b.free % 3) == 1
    # clamped node carries half an element of load, the rest is on free DOFs
    assert -b.f[v].sum() == pytest.approx(p.weight * (1 - 0.5 / p.n_elements), rel=1e-12)


@pytest.mark.parametrize(
    "key,kw",
    [
        ("thickness", {"thickness": 0}),
        ("n_elements", {"n_elements": 0}),
        ("mass", {"mass": "diagonal"}),
        ("poisson_ratio", {"poisson_ratio": 0.7}),
    ],
)
def test_params_validation_names_key(key, kw):
    with pytest.raises(ValueError, match=key):
        BeamParams(**kw)


def test_friction_table_semantics(tmp_path):
    f = tmp_path / "mu.csv"
    f.write_text("relative_velocity_mm_per_s,mu\n0,0.5\n0.3,0.45\n0.6,0.4\n1.2,0.4\n")
    t = FrictionTable.from_csv(f)
    assert t.static == 0.5
    assert t(-0.3) == pytest.approx(0.45)
    assert t(5.0) == pytest.approx(0.4)
    assert t.slope(0.5) == pytest.approx(-1 / 6)
    assert t.slope(1.0) == 0.0
    with pytest.raises(ValueError, match="speeds"):
        FrictionTable((0.1, 0.2), (0.5, 0.4))


def test_mode_amplitude_recovers_a_growing_mode_under_fast_chatter():
    """Complex demodulation: a 366 Hz component growing at 0.4 1/s under a 12.9 kHz chatter of twice its
    size and an offset comes out at its own amplitude, and its log-slope is the growth rate."""
    from stickslip.fe.metrics import leading_growth_rate, mode_amplitude

    t = np.arange(0.0, 1.0, 2.5e-6)
    x = 3e-5 + 1e-5 * np.exp(0.4 * t) * np.sin(2 * np.pi * 366.0 * t) + 2e-5 * np.sin(2 * np.pi * 12900 * t)
    tc, amp = mode_amplitude(t, x, 366.0, 0.05)
    np.testing.assert_allclose(amp, 1e-5 * np.exp(0.4 * tc), rtol=2e-3)
    rate, end = leading_growth_rate(tc, amp)
    assert rate == pytest.approx(0.4, rel=1e-2) and end == pytest.approx(tc[-1])


def test_leading_growth_rate_stops_at_a_collapse_and_keeps_a_decay_whole():
    t = np.linspace(0.0, 1.0, 21)
    grow = np.exp(0.5 * t)
    collapsed = np.where(t < 0.42, grow, 0.8 * grow)  # a burst ends the growth at 0.42 s
    rate, end = leading_growth_rate_of(t, collapsed)
    assert rate == pytest.approx(0.5, rel=1e-9) and end == pytest.approx(0.4)
    decay = np.exp(-16.5 * t)  # falls below 95 % at once but never grew: fitted over every sample
    assert leading_growth_rate_of(t, decay) == (pytest.approx(-16.5, rel=1e-9), pytest.approx(1.0))
    assert np.isnan(leading_growth_rate_of(t[:2], grow[:2])[0])


def leading_growth_rate_of(t, a):
    from stickslip.fe.metrics import leading_growth_rate

    return leading_growth_rate(t, a)
