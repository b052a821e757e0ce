"""Defining properties of each friction variant, and what is inconsistent between them."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from stickslip.model import PAPER_BASELINE, BeltModel, BeltParams, ParameterError, friction_law


def test_printed_variants_cannot_stick_consistent_can():
    assert not friction_law(PAPER_BASELINE, "eq3_printed").can_stick
    assert not friction_law(PAPER_BASELINE, "eq4_printed").can_stick
    assert friction_law(PAPER_BASELINE, "consistent").can_stick


@given(v=st.floats(-5, 5), vb=st.floats(0, 2))
def test_consistent_is_eq3_with_the_sign_reversed(v, vb):
    eq3 = friction_law(PAPER_BASELINE, "eq3_printed")
    cons = friction_law(PAPER_BASELINE, "consistent")
    assert cons.force(v, vb) == pytest.approx(-eq3.force(v, vb), abs=1e-12)


@given(v=st.floats(-5, 5), vb=st.floats(0.01, 2))
def test_eq4_differs_from_eq3_only_in_the_sigma_vb_term(v, vb):
    p = PAPER_BASELINE
    eq3, eq4 = friction_law(p, "eq3_printed"), friction_law(p, "eq4_printed")
    # Eq. 4 is Eq. 3 rearranged but prints sigma*V_b where mu_s*N*sigma*V_b belongs
    expected = (p.mu_s * p.normal_force - 1.0) * p.sigma * vb
    assert eq3.force(v, vb) - eq4.force(v, vb) == pytest.approx(expected, abs=1e-12)


@given(vr=st.floats(0.001, 1.5))
def test_consistent_friction_opposes_relative_velocity_and_falls_with_slope_sigma(vr):
    p = PAPER_BASELINE
    law = friction_law(p, "consistent")
    vb = 0.5
    forward = law.force(vb + vr, vb)  # mass faster than the belt: friction pulls it back
    backward = law.force(vb - vr, vb)
    mu_n = p.mu_s * p.normal_force
    assert forward == pytest.approx(-mu_n * (1 - p.sigma * vr))
    assert backward == pytest.approx(mu_n * (1 - p.sigma * vr))


def test_printed_sign_pushes_away_from_the_belt_velocity():
    law = friction_law(PAPER_BASELINE, "eq3_printed")
    vb = 0.5
    assert law.force(vb + 0.1, vb) > 0  # mass faster than belt: pushed faster still
    assert law.force(vb - 0.1, vb) < 0


def test_zero_slip_damping_at_the_text_sigma():
    # C = sigma mu_s N exactly for the text values: the slip phase is undamped
    model = BeltModel.build(PAPER_BASELINE, "consistent")
    assert model.slip_damping() == pytest.approx(0.0, abs=1e-15)
    assert BeltModel.build(PAPER_BASELINE, "eq3_printed").slip_damping() == pytest.approx(3.0)


def test_stick_release_position_is_independent_of_sigma():
    for sigma in (0.1, 0.3, 0.5):
        model = BeltModel.build(PAPER_BASELINE.with_(sigma=sigma), "consistent")
        assert model.stick_release_position() == pytest.approx((5.0 - 1.5 * 0.5) / 5.0)


@pytest.mark.parametrize(
    "key,value",
    [
        ("mass", 0.0),
        ("mass", -1.0),
        ("stiffness", float("nan")),
        ("normal_force", 0),
        ("damping", -0.1),
        ("sigma", float("inf")),
        ("mass", "1"),
        ("mass", True),
        ("units", "imperial"),
    ],
)
def test_bad_parameters_name_the_key(key, value):
    with pytest.raises(ParameterError, match=key):
        PAPER_BASELINE.with_(**{key: value})


def test_from_mapping_names_unknown_and_missing_keys():
    good = PAPER_BASELINE.as_dict()
    with pytest.raises(ParameterError, match="masss"):
        BeltParams(**{**good, "masss": 1.0})
    del good["stiffness"]
    with pytest.raises(ParameterError, match="stiffness"):
        BeltParams(**good)


def test_si_units_reading_scales_the_mass():
    si = PAPER_BASELINE.with_(units="si")
    assert si.effective_mass == pytest.approx(1e-3)
    model = BeltModel.build(si, "consistent")
    omega = np.sqrt(si.stiffness / model.mass)
    assert omega / (2 * np.pi) == pytest.approx(11.25, rel=1e-3)  # far from the reported 0.25 Hz


_floats = st.one_of(
    st.floats(-1e3, 1e3, allow_nan=False), st.sampled_from([0.0, -0.0, 0.5, 0.6, -0.6, float("nan")])
)


@given(
    variant=st.sampled_from(["consistent", "eq3_printed", "eq4_printed"]),
    plateau=st.sampled_from([float("inf"), 0.6]),
    deceleration=st.sampled_from([0.0, 0.025]),
    t=st.floats(0.0, 40.0),
    x=_floats,
    v=_floats,
)
def test_scalar_right_hand_side_is_bit_identical_to_the_array_form(variant, plateau, deceleration, t, x, v):
    """BeltModel.rhs evaluates one state in Python floats; it must give the very bits of the array form
    (acceleration on 1-element arrays: np.sign, np.maximum, np.clip), signed zeros and NaN included."""
    params = BeltParams(
        **{**PAPER_BASELINE.as_dict(), "plateau_speed": plateau, "belt_deceleration": deceleration}
    )
    model = BeltModel.build(params, variant)
    fast = model.rhs(t, np.array([x, v]))
    slow = model.acceleration(np.array([t]), np.array([x]), np.array([v]))[0]
    assert fast[0] == v or (np.isnan(fast[0]) and np.isnan(v))
    assert np.array_equal(fast[1:], np.atleast_1d(slow), equal_nan=True)
    assert np.signbit(fast[1]) == np.signbit(slow)


def _one_wording_cases():
    from stickslip.analysis.sweep import chunk_count
    from stickslip.fe.continuum import strip_mesh
    from stickslip.fe.params import BeamParams
    from stickslip.model.laws import AffineLaw
    from stickslip.solvers import SwitchSolver

    return [
        ("mass", lambda v: PAPER_BASELINE.with_(mass=v)),  # a parameter set (dataclass)
        ("mu_s", lambda v: AffineLaw(v, 0.3)),  # a friction law, by position
        ("rtol", lambda v: SwitchSolver(rtol=v)),  # a solver setting
        ("length", lambda v: BeamParams(length=v)),  # an FE parameter set (model)
        ("nx", lambda v: strip_mesh(BeamParams(), v, 1)),  # a function's argument
        ("chunk_size", lambda v: chunk_count([], v)),
    ]


@pytest.mark.parametrize("key,build", _one_wording_cases(), ids=[k for k, _ in _one_wording_cases()])
def test_every_checked_value_is_refused_in_one_wording_naming_its_key(key, build):
    """Parameter sets, laws, solver settings, FE parameters and function arguments are all checked by pydantic
    from their declared types: the same bad value gets the same message, which starts with the key."""
    too_small = rf"^{key}: input should be greater than (or equal to )?[01], got 0$"
    with pytest.raises(ParameterError, match=too_small):
        build(0)
    with pytest.raises(ParameterError, match=rf"^{key}: input should be a valid (number|integer), got True$"):
        build(True)
