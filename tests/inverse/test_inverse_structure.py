"""Structural identifiability derived from the equations (stickslip.inverse.structure): exact ranks."""

import numpy as np
import pytest
import sympy as sp

from stickslip.inverse.structure import (
    SYMBOLS,
    _fibre_functions,
    fibre_extent,
    identifiable_in_structure,
    phase_combinations,
    runs_rank,
)

FREE = ("sigma", "damping", "mu_s", "normal_force", "stiffness", "mass")
VB = (("belt_velocity", 0.5),)


def test_fig02_motion_depends_on_three_combinations_k_m_slip_damping_and_release_position():
    """Stick, then backward slip (Fig. 2, consistent reading): K/M, (C - mu_s N sigma)/M and the release
    position x_r = (mu_s N - C V_b)/K fix the motion; the slip equilibrium is x_r + (C - mu_s N sigma)
    V_b / K, so it adds nothing, and the rank is 3 for six free parameters."""
    combos = phase_combinations(("stick", "slip_backward"))
    m, k, c, mu, n, sigma, vb = (SYMBOLS[q] for q in ("mass", "stiffness", "damping", "mu_s", "normal_force",
                                                         "sigma", "belt_velocity"))  # fmt: skip
    assert sp.simplify(combos["K/M"] - k / m) == 0
    assert sp.simplify(combos["(C - mu_s N sigma)/M"] - (c - mu * n * sigma) / m) == 0
    assert sp.simplify(combos["x_r"] - (mu * n - c * vb) / k) == 0
    assert sp.simplify(combos["x_e(-1)"] - combos["x_r"] - (c - mu * n * sigma) * vb / k) == 0
    assert runs_rank(((("stick", "slip_backward"), VB, ()),), FREE) == 3


def test_each_phase_adds_what_its_equation_adds():
    assert runs_rank(((("slip_backward",), VB, ()),), FREE) == 3  # K/M, slip damping, equilibrium
    assert runs_rank(((("stick", "slip_backward", "slip_forward"), VB, ()),), FREE) == 4  # mu_s N/K apart
    plateau = FREE + ("plateau_speed",)
    assert runs_rank(((("stick", "slip_backward", "plateau"), VB, ()),), plateau) == 5  # C/M apart, v_p


def test_a_quantity_off_the_row_space_is_never_a_point():
    runs = ((("stick", "slip_backward"), VB, ()),)
    assert runs_rank(runs, FREE) == 3
    k_over_m = tuple(float(x) for x in (0, 0, 0, 0, 1, -1))  # exponents over FREE
    c_over_m = (0.0, 1.0, 0.0, 0.0, 0.0, -1.0)
    sigma = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert identifiable_in_structure(runs, FREE, k_over_m)
    assert not identifiable_in_structure(runs, FREE, c_over_m)
    assert not identifiable_in_structure(runs, FREE, sigma)


def test_the_derivation_uses_the_models_own_law_and_thresholds():
    """The symbolic law and the derived slip damping and release position are the model's
    (``friction_law``, ``BeltModel.slip_damping``, ``BeltModel.stick_release_position``) at a parameter set
    away from the stated one; exact rationals against floats, so 1e-12 relative is round-off only."""
    from stickslip.inverse.structure import consistent_law
    from stickslip.model import BeltParams
    from stickslip.model.equations import BeltModel
    from stickslip.model.friction import friction_law

    values = dict(mass=1.3, stiffness=4.1, damping=0.7, mu_s=0.45, sigma=0.35, normal_force=12.0)
    params = BeltParams(**values, belt_velocity=0.8)
    subs = {SYMBOLS[k]: sp.Rational(str(v)) for k, v in {**values, "belt_velocity": 0.8}.items()}
    law = friction_law(params, "consistent")
    for derived, coded in zip(consistent_law(), (law.a, law.b, law.kappa)):
        assert float(derived.subs(subs)) == pytest.approx(coded, rel=1e-12)
    combos = phase_combinations(("stick", "slip_backward"))
    model = BeltModel(params, law)
    assert float(combos["(C - mu_s N sigma)/M"].subs(subs)) == pytest.approx(
        model.slip_damping() / params.mass, rel=1e-12
    )
    assert float(combos["x_r"].subs(subs)) == pytest.approx(model.stick_release_position(), rel=1e-12)


def test_the_plateau_switch_speed_is_a_combination():
    combos = phase_combinations(("stick", "slip_backward", "plateau"))
    assert combos["v_p"] == SYMBOLS["plateau_speed"]
    assert sp.simplify(combos["C/M"] - SYMBOLS["damping"] / SYMBOLS["mass"]) == 0


def test_the_fibre_of_fig02_holds_the_curved_ridge_and_nothing_off_it():
    """Fig. 2's fibre through the stated set: every set with K/M, (C - mu_s N sigma)/M and x_r unchanged.
    The curve C -> (mu_s N = K x_r + C V_b, sigma = (C - gamma) / mu_s N) lies on it, so the extents of
    sigma, C and mu_s N found over the fibre contain the curve's (1e-9 in log10: the optimiser's end points
    are checked on the fibre to 1e-8 relative); K/M does not move (its extent is a point to 1e-9)."""
    runs = ((("stick", "slip_backward"), VB, ()),)
    stated = dict(sigma=0.5, damping=1.5, mu_s=0.5, normal_force=10.0, stiffness=5.0, mass=1.0)
    bounds = dict(sigma=(0.01, 2), damping=(0.01, 20), mu_s=(0.05, 1.5), normal_force=(1, 100),
                  stiffness=(0.5, 50), mass=(0.1, 10))  # fmt: skip
    u0 = np.log10([stated[q] for q in FREE])
    lo, hi = (np.log10([bounds[q][i] for q in FREE]) for i in (0, 1))
    x_r = (stated["mu_s"] * stated["normal_force"] - stated["damping"] * 0.5) / stated["stiffness"]
    gamma = stated["damping"] - stated["mu_s"] * stated["normal_force"] * stated["sigma"]
    curve = []
    for c in (0.5, 1.0, 2.0, 3.0):
        mu_n = stated["stiffness"] * x_r + c * 0.5
        curve.append(
            {**stated, "damping": c, "mu_s": mu_n / stated["normal_force"], "sigma": (c - gamma) / mu_n}
        )
    values, _ = _fibre_functions(runs, FREE)
    for point in curve:
        np.testing.assert_allclose(values(np.log10([point[q] for q in FREE])), values(u0), rtol=1e-12)
    rows = np.vstack([np.eye(6), [0, 0, 0, 0, 1, -1]])
    ext = fibre_extent(runs, FREE, u0, rows, lo, hi)
    for i, q in enumerate(FREE):
        along = np.log10([point[q] for point in curve])
        assert ext[i, 0] <= along.min() + 1e-9 and ext[i, 1] >= along.max() - 1e-9, q
    assert ext[-1, 1] - ext[-1, 0] < 1e-9  # K/M
    assert ext[0, 1] - ext[0, 0] > 0.5  # sigma: a range of more than half a decade


def test_the_rank_at_rational_points_is_the_symbolic_rank_for_every_phase_set():
    """``generic_rank`` (ranks at two rational points, exact arithmetic) equals sympy's rank of the symbolic
    Jacobian, simplified, for every set of phases a run can visit, with and without the plateau speed free."""
    from itertools import combinations

    from stickslip.inverse.structure import PHASES, generic_rank

    for free in (FREE, FREE + ("plateau_speed",)):
        for n in range(1, len(PHASES) + 1):
            for phases in combinations(PHASES, n):
                combos = list(phase_combinations(phases).values())
                subs = {SYMBOLS["belt_velocity"]: sp.Rational(1, 2)}
                rows = [[SYMBOLS[q] * sp.diff(e, SYMBOLS[q]) for q in free] for e in combos]
                symbolic = sp.Matrix(rows).subs(subs).rank(simplify=True)
                assert generic_rank(sp.Matrix(rows).subs(subs).tolist()) == symbolic, (free, phases)
