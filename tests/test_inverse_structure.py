"""Structural identifiability derived from the equations (stickslip.inverse.structure): exact ranks."""

import sympy as sp

from stickslip.inverse.structure import (
    SYMBOLS,
    identifiable_in_structure,
    phase_combinations,
    runs_rank,
    structural_rank,
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
    assert structural_rank(("stick", "slip_backward"), FREE, VB) == 3


def test_each_phase_adds_what_its_equation_adds():
    assert structural_rank(("slip_backward",), FREE, VB) == 3  # K/M, slip damping, equilibrium
    assert structural_rank(("stick", "slip_backward", "slip_forward"), FREE, VB) == 4  # mu_s N/K apart
    plateau = FREE + ("plateau_speed",)
    assert structural_rank(("stick", "slip_backward", "plateau"), plateau, VB) == 5  # C/M apart, v_p


def test_a_quantity_off_the_row_space_is_never_a_point():
    runs = ((("stick", "slip_backward"), VB, ()),)
    assert runs_rank(runs, FREE) == 3
    k_over_m = tuple(float(x) for x in (0, 0, 0, 0, 1, -1))  # exponents over FREE
    c_over_m = (0.0, 1.0, 0.0, 0.0, 0.0, -1.0)
    sigma = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert identifiable_in_structure(runs, FREE, k_over_m)
    assert not identifiable_in_structure(runs, FREE, c_over_m)
    assert not identifiable_in_structure(runs, FREE, sigma)
