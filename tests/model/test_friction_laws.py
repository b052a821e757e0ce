"""Friction laws (model/laws.py): closed forms, the laws' defining properties, and bad input named by key."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.model.friction import friction_law
from stickslip.model.laws import (
    AffineLaw,
    CoulombLaw,
    LawModel,
    RationalLaw,
    StribeckLaw,
    TabulatedLaw,
    law_from_config,
    law_from_reading,
)
from stickslip.model.params import ParameterError

coef = st.floats(0.05, 2.0)
speeds = st.floats(0.0, 50.0)
TABLE_V = np.array([0.0, 0.05, 0.2, 0.4, 0.8, 1.2])
TABLE_MU = np.array([0.5, 0.48, 0.44, 0.41, 0.40, 0.40])


@st.composite
def laws(draw):
    """One law of each kind with random parameters (bounded laws: 0 <= mu <= static everywhere)."""
    kind = draw(st.sampled_from(["affine_plateau", "coulomb", "stribeck", "rational", "tabulated"]))
    mu_s = draw(coef)
    mu_k = mu_s * draw(st.floats(0.0, 1.0))
    if kind == "affine_plateau":
        vp = draw(st.floats(0.01, 5.0))
        return AffineLaw(mu_s, draw(st.floats(0.0, 1.0)) / vp, vp)  # sigma v_p <= 1: mu stays >= 0
    if kind == "coulomb":
        return CoulombLaw(mu_s, max(mu_k, 1e-3 * mu_s))
    if kind == "stribeck":
        return StribeckLaw(mu_s, mu_k, draw(st.floats(0.01, 5.0)))
    if kind == "rational":
        return RationalLaw(mu_s, draw(st.floats(0.0, 20.0)), mu_k)
    return TabulatedLaw(TABLE_V, TABLE_MU * mu_s / 0.5)


def lipschitz(law):
    """A bound on |d mu / d speed| where the law is continuous (speed > 0)."""
    if isinstance(law, AffineLaw):
        return law.mu_s * law.sigma
    if isinstance(law, CoulombLaw):
        return 0.0
    if isinstance(law, StribeckLaw):
        return (law.mu_s - law.mu_k) / law.v_s
    if isinstance(law, RationalLaw):
        return (law.mu_s - law.mu_k) * law.delta
    secants = np.abs(np.diff(law.values) / np.diff(law.speed))
    return 3.0 * float(np.max(secants))  # PCHIP's slopes are within 3x the neighbouring secants


@settings(max_examples=200, deadline=None)
@given(law=laws(), speed=st.floats(1e-9, 20.0), h=st.floats(1e-12, 1e-3))
def test_mu_is_lipschitz_continuous_in_slip(law, speed, h):
    jump = abs(float(law.mu(speed + h)) - float(law.mu(speed)))
    assert jump <= lipschitz(law) * h * (1 + 1e-9) + 1e-15


@settings(max_examples=200, deadline=None)
@given(law=laws(), speed=speeds)
def test_mu_is_bounded_by_the_static_limit(law, speed):
    mu = float(law.mu(speed))
    assert 0.0 <= mu <= law.static * (1 + 1e-12)
    assert law.kinetic_limit <= law.static * (1 + 1e-12)


@settings(max_examples=200, deadline=None)
@given(law=laws(), vr=st.floats(-50.0, 50.0), normal=st.floats(0.1, 100.0))
def test_friction_force_is_odd_and_opposes_the_relative_velocity(law, vr, normal):
    f_plus, f_minus = float(law.force(vr, normal)), float(law.force(-vr, normal))
    assert f_plus == -f_minus
    assert f_plus * vr <= 0.0
    assert abs(f_plus) <= normal * law.static * (1 + 1e-12)


@settings(max_examples=200, deadline=None)
@given(
    mu_s=coef,
    sigma=st.floats(0.0, 1.0),
    plateau=st.one_of(st.just(math.inf), st.floats(0.05, 3.0)),
    v=st.floats(-5.0, 5.0),
    vb=st.floats(0.0, 2.0),
)
def test_affine_law_reproduces_the_consistent_reading(mu_s, sigma, plateau, v, vb):
    params = PAPER_BASELINE.with_(mu_s=mu_s, sigma=sigma, plateau_speed=plateau)
    old = friction_law(params, "consistent")
    law = law_from_reading(params, "consistent")
    assert float(law.force(v - vb, params.normal_force)) == pytest.approx(
        float(old.force(v, vb)), rel=1e-12, abs=1e-12
    )
    assert law.static * params.normal_force == pytest.approx(-old.a, rel=1e-15)


def test_closed_forms_of_the_smooth_laws():
    assert float(StribeckLaw(0.5, 0.3, 0.2).mu(0.2)) == pytest.approx(0.3 + 0.2 / math.e, rel=1e-15)
    assert float(StribeckLaw(0.5, 0.3, 0.2).mu(0.0)) == 0.5  # continuous at 0+: no static/kinetic jump
    assert float(RationalLaw(0.5, 2.0).mu(0.5)) == pytest.approx(0.25, rel=1e-15)
    assert float(RationalLaw(0.5, 2.0, mu_k=0.1).mu(0.5)) == pytest.approx(0.3, rel=1e-15)
    assert float(AffineLaw(0.5, 0.3, 0.6).mu(5.0)) == pytest.approx(0.5 * (1 - 0.18), rel=1e-15)
    jump = CoulombLaw(0.5, 0.4)
    assert (jump.static, jump.kinetic_limit, float(jump.mu(3.0))) == (0.5, 0.4, 0.4)


def test_table_passes_through_its_rows_without_overshoot_and_holds_the_last_value():
    law = TabulatedLaw(TABLE_V, TABLE_MU)
    assert np.array_equal(law.mu(TABLE_V), TABLE_MU)
    fine = np.linspace(0.0, TABLE_V[-1], 20001)
    mu = law.mu(fine)
    assert np.all(np.diff(mu) <= 1e-15)  # the table is non-increasing, so is its interpolant (PCHIP)
    assert float(law.mu(10.0)) == TABLE_MU[-1] and law.static == TABLE_MU[0]


def test_table_reads_csv_and_netcdf_alike(tmp_path):
    import xarray as xr

    csv = tmp_path / "mu.csv"
    rows = "".join(f"{v},{m}\n" for v, m in zip(TABLE_V, TABLE_MU))
    csv.write_text("relative_velocity_mm_per_s,mu\n" + rows)
    nc = tmp_path / "mu.nc"
    xr.Dataset({"mu": ("relative_speed", TABLE_MU)}, coords={"relative_speed": TABLE_V}).to_netcdf(nc)
    from_csv = law_from_config({"kind": "tabulated", "path": str(csv)})
    from_nc = law_from_config({"kind": "tabulated", "path": str(nc)})
    probe = np.linspace(0, 2, 101)
    assert np.array_equal(from_csv.mu(probe), from_nc.mu(probe))
    assert from_csv.describe()["rows"] == len(TABLE_V)


@pytest.mark.parametrize(
    "entry, key",
    [
        ({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3, "v_s": float("nan")}, "law.v_s"),
        ({"kind": "coulomb", "mu_s": 0.5, "mu_k": 0.6}, "law.mu_k"),
        ({"kind": "coulomb", "mu_s": 0.5, "mu_k": float("inf")}, "law.mu_k"),
        ({"kind": "rational", "mu_s": 0.5, "delta": -1.0}, "law.delta"),
        ({"kind": "affine", "mu_s": 0.5, "sigma": 0.5, "slope": 1}, "law.slope"),
        ({"kind": "affine", "mu_s": "0.5", "sigma": 0.5}, "law.mu_s"),
        ({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3}, "law.v_s"),
        ({"kind": "spline"}, "law.kind"),
        ({"kind": "tabulated", "path": "/nonexistent/mu.csv"}, "law.path"),
    ],
)
def test_bad_law_config_names_the_key(entry, key):
    with pytest.raises(ParameterError, match=rf"^{key.replace('.', '[.]')}\b"):
        law_from_config(entry)


def test_bad_tables_are_refused():
    with pytest.raises(ParameterError, match="first relative speed must be 0"):
        TabulatedLaw(TABLE_V + 0.1, TABLE_MU)
    with pytest.raises(ParameterError, match="strictly increasing"):
        TabulatedLaw(np.array([0.0, 0.4, 0.2]), TABLE_MU[:3])
    with pytest.raises(ParameterError, match="finite"):
        TabulatedLaw(TABLE_V, np.where(TABLE_V > 1, np.nan, TABLE_MU))
    with pytest.raises(ParameterError, match="exceeds the static limit"):
        TabulatedLaw(TABLE_V, TABLE_MU, static_mu=0.3)


def test_printed_sign_variants_are_not_friction_laws():
    with pytest.raises(ParameterError, match="^variant: 'eq3_printed'"):
        LawModel.from_belt_model(BeltModel.build(PAPER_BASELINE, "eq3_printed"))


@settings(max_examples=300, deadline=None)
@given(speed=st.floats(-0.05, 3.0))
def test_table_scalar_path_equals_the_vectorised_interpolant(speed):
    law = TabulatedLaw(TABLE_V, TABLE_MU)
    assert law.mu_continued(float(speed)) == pytest.approx(
        float(law.mu_continued(np.array(speed))), abs=1e-15
    )


@settings(max_examples=100, deadline=None)
@given(t=st.floats(0.0, 30.0), x=st.floats(-3.0, 3.0), v=st.floats(-3.0, 3.0))
def test_affine_law_as_one_sign_equation_is_the_pipelines_equation(t, x, v):
    """The methods study runs any law through SignLawModel; for the affine law it must be BeltModel.rhs."""
    from stickslip.validation.methods import SignLawModel

    model = BeltModel.build(PAPER_BASELINE.with_(sigma=0.5, belt_deceleration=0.02), "consistent")
    single = SignLawModel.from_belt_model(model)
    assert np.allclose(single.rhs(t, [x, v]), model.rhs(t, [x, v]), rtol=1e-13, atol=1e-13)
