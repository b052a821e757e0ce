"""Identifiable dimensions from chi-square profiles (exact and near-exact ridges), parameter ranges along the
ridges, and minimal conflicting subsets of a figure's reported numbers."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from stickslip.inverse.conflicts import minimal_conflicts
from stickslip.inverse.forward import Forward
from stickslip.inverse.identify import PROFILE_THRESHOLD, identify, on_ridge, parameter_ranges
from stickslip.inverse.problem import build_problem
from stickslip.inverse.study import fit_problem, summary_rows

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def fig02(config, claims):
    """Fig. 2 under the consistent reading, fitted as the study fits it (default settings)."""
    problem = build_problem(config, claims, "fig02", "consistent")
    return fit_problem(problem, config.inverse.mode_settings, steps=0, conflicts=False)


def _chi2(forward, values):
    r = forward.residuals(values)
    return float(r @ r)


def test_fig02_straight_line_profiles_see_the_structural_ridges_only(fig02):
    """The straight-line analysis (``identify``: chi-square along every direction of the structural null space
    and the Jacobian's singular directions) finds the two structural ridges of Fig. 2 (12 numbers, 6 free
    parameters) and nothing else: 4 dimensions by that analysis alone (the curved ridge of
    ``test_fig02_exact_curved_ridge_makes_sigma_damping_and_mu_s_n_ranges`` is invisible to it). Checked
    against two profiles through the damping C computed here independently:

    * C alone (every other parameter at the best fit) from 0.5 to 5 N s/mm: chi-square rises far above the
      threshold, so C/M is pinned and no ridge runs along C alone;
    * C with K, M and N scaled by the same factor (K/M, C/M, mu_s N/M unchanged) from 0.5 to 5 N s/mm:
      chi-square is constant to round-off, an exact ridge. It is one of the two ridges the profiles find, and
      C is reported as a range covering 0.5-5, not as a point.
    """
    p, forward, fit = fig02.problem, Forward(fig02.problem), fig02.fit
    ident = fig02.identification
    assert ident.dimensions == 4 and len(ident.ridge_directions) == 2  # this analysis alone
    assert all(r.structural for r in ident.ridge_directions)

    best = fit.free_values
    chi2_best = _chi2(forward, best)
    i_c = p.free.index("damping")
    alone = []
    for c in np.geomspace(0.5, 5.0, 7):
        v = best.copy()
        v[i_c] = c
        r = forward.residuals(v)
        alone.append(float(r @ r) if np.all(np.isfinite(r)) else np.inf)
    assert max(alone) - chi2_best > 100 * PROFILE_THRESHOLD

    mask = np.array([q in ("damping", "stiffness", "mass", "normal_force") for q in p.free])
    ridge = []
    for c in np.geomspace(0.5, 5.0, 7):
        f = c / best[i_c]
        v = best * np.where(mask, f, 1.0)
        assert p.in_bounds(v)
        ridge.append(_chi2(forward, v))
    assert np.ptp(ridge + [chi2_best]) < 1e-9 * max(chi2_best, 1.0)

    # the scaling direction lies in the span of the ridges the profiles found
    d = mask / np.linalg.norm(mask.astype(float))
    span = np.column_stack([r.direction for r in ident.ridge_directions])
    coef, *_ = np.linalg.lstsq(span, d, rcond=None)
    assert np.linalg.norm(span @ coef - d) < 1e-9

    lower, upper = parameter_ranges(p, best, ident)
    flat = on_ridge(lower, upper)
    assert flat[i_c] and lower[i_c] <= 0.5 and upper[i_c] >= 5.0


def _fig02_ridge(problem, best, damping):
    """The issue's curve through the best fit: C -> (mu_s N = K x_e + C V_b, sigma = (C - gamma) / mu_s N),
    x_e = (mu_s N - C V_b) / K and gamma = C - mu_s N sigma at the best fit (N, K, M kept). In slip (v_r < 0
    throughout Fig. 2's motion) the consistent law gives M x'' + gamma x' + K (x - x_e) = gamma V_b, and stick
    ends at x = x_e: the motion depends on C, mu_s N, sigma only through x_e and gamma."""
    d = dict(zip(problem.free, best))
    vb, mu_n = problem.stated["belt_velocity"], d["mu_s"] * d["normal_force"]
    x_e, gamma = (mu_n - d["damping"] * vb) / d["stiffness"], d["damping"] - mu_n * d["sigma"]
    out = []
    for c in damping:
        mn = d["stiffness"] * x_e + c * vb
        v = {**d, "damping": c, "mu_s": mn / d["normal_force"], "sigma": (c - gamma) / mn}
        out.append(np.array([v[q] for q in problem.free]))
    return out


def test_fig02_exact_curved_ridge_makes_sigma_damping_and_mu_s_n_ranges(fig02):
    """Along the curve of ``_fig02_ridge`` (C = 0.25 ... 4, sigma 0.22 ... 0.58 at this best fit) chi-square
    is constant: the same motion, so the only differences are the solver's round-off (event times found to
    ~1e-12 relative). Tolerance 1e-9 x chi-square: a thousand times that round-off, and below any real change
    a parameter could make (the metrics move in steps of the 0.01 s sampling, ~1e-3 relative). The curve is
    not a straight line in log10 (sigma and mu_s N bend against C), so the straight-line profiles miss it;
    the profile likelihood finds it: 3 identifiable dimensions, and sigma, C/M and mu_s N/M reported as
    ranges (no point) that contain the whole curve, as do the ranges of C, mu_s and N."""
    p, forward, fit = fig02.problem, Forward(fig02.problem), fig02.fit
    best = fit.free_values
    damping = [0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0]
    curve = _fig02_ridge(p, best, damping)
    assert all(p.in_bounds(v) for v in curve)
    chi2_best = _chi2(forward, best)
    values = [_chi2(forward, v) for v in curve]
    assert np.ptp(values + [chi2_best]) <= 1e-9 * chi2_best
    sig = [v[p.free.index("sigma")] for v in curve]
    assert min(sig) < 0.25 and max(sig) > 0.55  # a wide stretch of sigma, not a point
    logs = np.log10(curve)
    chord = (logs[-1] - logs[0]) / np.linalg.norm(logs[-1] - logs[0])
    off_line = [np.linalg.norm((u - logs[0]) - ((u - logs[0]) @ chord) * chord) for u in logs]
    assert max(off_line) > 0.05  # curved: 0.05 decades off the chord of its ends

    pid, a = fig02.profile, fig02.analysis
    # the dimension is derived from the equations (stickslip.inverse.structure), so it is 3 on every CPU; the
    # profile likelihood runs over the quantities the structure leaves identifiable (K/M) and reports what
    # the data bound there
    assert fig02.structural_dimensions == 3 and a.dims == 3 and pid.dimensions == 3
    assert fig02.phases == (("stick", "slip_backward"),)
    assert set(pid.profiles) == {"K/M"}
    summary = summary_rows("fig02", {"consistent": fig02})[0]
    assert summary["identifiable_dimensions"] == 3 and summary["structural_dimensions"] == 3
    assert summary["dimensions_note"] == ""
    assert summary["profiles_bounded"] in ("0 of 1", "1 of 1")  # K/M: what the data bound is theirs to say
    m = best[p.free.index("mass")]
    on_curve = {
        "sigma": sig,
        "damping": damping,
        "mu_s": [v[p.free.index("mu_s")] for v in curve],
        "C_over_M": [c / m for c in damping],
        "mu_s_N_over_M": [v[p.free.index("mu_s")] * v[p.free.index("normal_force")] / m for v in curve],
    }
    for key, along in on_curve.items():
        assert summary[f"best_{key}"] == "" and summary[f"identifiable_{key}"] == 0, key
        assert summary[f"lower_{key}"] <= min(along) * (1 + 1e-3), key
        assert summary[f"upper_{key}"] >= max(along) * (1 - 1e-3), key
    assert summary["identifiable_K_over_M"] == 1 and summary["best_K_over_M"] != ""


class Linear:
    """A forward model stand-in: residuals linear in log10 of the free parameters, r = A (u - u*)."""

    def __init__(self, problem, a, u_star):
        self.problem, self.a, self.u_star = problem, np.asarray(a, float), np.asarray(u_star, float)
        self.evaluations = 0

    def residuals(self, values):
        self.evaluations += 1
        return self.a @ (np.log10(np.asarray(values, float)) - self.u_star)


def _linear_problem(config, claims, singular_values, numbers=6, seed=0):
    """A figure problem whose residuals have the given singular values in its identifiable coordinates."""
    p = build_problem(config, claims, "fig02", "consistent")
    p = replace(p, observations=p.observations[:numbers])
    basis = p.identifiable_basis()
    rng = np.random.default_rng(seed)
    q_left, _ = np.linalg.qr(rng.standard_normal((numbers, numbers)))
    q_right, _ = np.linalg.qr(rng.standard_normal((basis.shape[1], basis.shape[1])))
    s = np.zeros((numbers, basis.shape[1]))
    s[np.arange(len(singular_values)), np.arange(len(singular_values))] = singular_values
    a = q_left @ s @ q_right.T @ basis.T
    return p, Linear(p, a, np.log10(p.stated_free))


def test_a_near_exact_ridge_is_seen_where_the_numerical_rank_is_full(config, claims):
    """Singular values 20, 20, 10 and 1e-4 in the 4 identifiable coordinates: the Jacobian has full numerical
    rank 4, but chi-square rises by ~1e-8 over the bounds along the weakest direction: a ridge. With the 2
    structural ones, 6 - 3 = 3 identifiable dimensions."""
    p, forward = _linear_problem(config, claims, [20.0, 20.0, 10.0, 1e-4])
    basis = p.identifiable_basis()
    assert np.linalg.matrix_rank(forward.a @ basis) == 4
    ident = identify(forward, p.stated_free)
    assert ident.dimensions == 3
    flat = [r for r in ident.ridge_directions if not r.structural]
    assert len(flat) == 1 and flat[0].singular_value == pytest.approx(1e-4, rel=1e-3)
    assert flat[0].rise < 1e-6


def test_a_moderate_direction_is_identifiable(config, claims):
    """Singular value 2 per log10 unit: a rise of 1 within half a decade, inside the bounds: pinned."""
    p, forward = _linear_problem(config, claims, [20.0, 20.0, 10.0, 2.0])
    ident = identify(forward, p.stated_free)
    assert ident.dimensions == 4
    weakest = min((r for r in ident.profiles if not r.structural), key=lambda r: r.singular_value)
    assert not weakest.ridge and 0.2 < weakest.t_upper - weakest.t_lower < 2.0


def test_fewer_numbers_than_identifiable_coordinates_leave_ridges(config, claims):
    """Two numbers fix at most two directions: of the 4 identifiable coordinates two are unconstrained."""
    p, forward = _linear_problem(config, claims, [20.0, 10.0], numbers=2)
    ident = identify(forward, p.stated_free)
    assert ident.dimensions == 2
    assert sum(r.unconstrained for r in ident.profiles) == 2


class Planted:
    """Residuals of five numbers in log10 of sigma (index 0) and C (index 1): numbers 0 and 1 want sigma
    two precisions apart (conflict as a pair), number 2 is 5 precisions off whatever the parameters
    (conflicts alone), numbers 3 and 4 are satisfiable with anything else."""

    def __init__(self, problem):
        self.problem, self.evaluations = problem, 0
        self.u0 = np.log10(problem.stated_free)

    def residuals(self, values):
        self.evaluations += 1
        u = np.log10(np.asarray(values, float)) - self.u0
        return np.array([u[0] / 0.01, (u[0] - 0.04) / 0.01, 5.0, u[1] / 0.05, (u[0] + u[1] - 0.01) / 0.05])


def test_minimal_conflicts_are_the_planted_ones(config, claims):
    p = build_problem(config, claims, "fig02", "consistent")
    p = replace(p, observations=p.observations[:5])
    forward = Planted(p)
    search = minimal_conflicts(forward, [p.stated_free], max_size=5)
    found = sorted(c.members for c in search.conflicts)
    assert found == [(0, 1), (2,)]
    assert search.complete and search.witness is None
    pair = next(c for c in search.conflicts if c.members == (0, 1))
    assert pair.worst == pytest.approx(2.0, abs=0.05)  # the best compromise: each number 2 precisions off

    capped = minimal_conflicts(Planted(p), [p.stated_free], max_size=1)
    assert [c.members for c in capped.conflicts] == [(2,)] and not capped.complete


class Satisfiable(Planted):
    """Numbers 0, 3 and 4 of ``Planted`` only: one parameter set satisfies them all."""

    def residuals(self, values):
        return super().residuals(values)[[0, 3, 4]]


def test_a_satisfiable_figure_has_no_conflict_and_a_witness(config, claims):
    p = build_problem(config, claims, "fig02", "consistent")
    p = replace(p, observations=p.observations[:3])
    forward = Satisfiable(p)
    start = p.stated_free * np.array([1.5, 1, 1, 1, 1, 1])  # every number off by ~18 precisions
    assert np.max(np.abs(forward.residuals(start))) > 1
    search = minimal_conflicts(forward, [start], max_size=3)
    assert search.conflicts == () and search.witness is not None
    assert np.all(np.abs(forward.residuals(search.witness)) <= 1.0)


def test_fig02_fit_ends_at_its_minimum_and_no_wide_interval_is_identifiable(fig02):
    """No profile point lies deeper than the fit by more than the restart tolerance (every fit ends at its
    minimum), and every quantity called identifiable spans at most a decade."""
    from stickslip.inverse.study import MINIMUM_TOL

    assert fig02.profile.floor >= fig02.fit.chi2 - MINIMUM_TOL
    summary = summary_rows("fig02", {"consistent": fig02})[0]
    for key in [k[len("identifiable_") :] for k in summary if k.startswith("identifiable_")]:
        if key != "dimensions" and summary[f"identifiable_{key}"] == 1:
            assert summary[f"upper_{key}"] <= 10 * summary[f"lower_{key}"], key


def test_an_unprofiled_fig02_still_gives_the_fibre_as_ranges(config, claims):
    """Without the profile likelihood (a figure the settings leave out, as the CI-size build does) sigma,
    C/M and mu_s N/M are still ranges: the fibre of the fit, from the equations (at least half a decade
    each: the Fig. 2 curve alone spans sigma 0.22-0.58 at the stated set's K/M), and K/M is still a point."""
    problem = build_problem(config, claims, "fig02", "consistent")
    settings = config.inverse.mode_settings.model_copy(update={"profile": ["no_figure"]})
    r = fit_problem(problem, settings, steps=0, conflicts=False)
    assert r.profile is None and r.structural_dimensions == 3
    row = summary_rows("fig02", {"consistent": r})[0]
    for key in ("sigma", "C_over_M", "mu_s_N_over_M"):
        assert row[f"identifiable_{key}"] == 0 and row[f"best_{key}"] == "", key
        assert row[f"upper_{key}"] > 10**0.5 * row[f"lower_{key}"], key
    assert row["identifiable_K_over_M"] == 1
