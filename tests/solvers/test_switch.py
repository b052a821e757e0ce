"""Switch-model solver (solvers/switch.py): the exact solver's cycles for affine laws, the textbook Coulomb
cycle, stick/pass-through decided by the static limit, and the common solver interface."""

import numpy as np
import pytest

from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.model.laws import AffineLaw, CoulombLaw, LawModel, StribeckLaw
from stickslip.model.params import ParameterError
from stickslip.solvers import STICK, Trajectory, make_solver
from stickslip.solvers.exact import ExactSwitchSolver, sample_segments
from stickslip.solvers.switch import SwitchSolver, contact_decision
from stickslip.validation.cycle import QUANTITIES, coulomb_cycle, cycle_quantities, record_from_segments

AGREE = 1e-9  # issue 13: affine laws on the two paths agree to 1e-9


def both(params, t_end=40.0):
    model = BeltModel.build(params, "consistent")
    return ExactSwitchSolver().segments(model, t_end), SwitchSolver().segments(model, t_end)


@pytest.mark.parametrize(
    "changes",
    [
        {"sigma": 0.5},  # the baseline of the captions (Fig. 17's table comes from this cycle)
        {"sigma": 0.5, "belt_velocity": 1.0},  # Fig. 5
        {"sigma": 0.5, "plateau_speed": 0.6},  # plateau: a breakpoint of the law inside slip
    ],
)
def test_affine_limit_cycle_agrees_with_the_exact_solver(changes):
    exact, switch = both(PAPER_BASELINE.with_(**changes))
    qa = cycle_quantities(record_from_segments(exact))
    qb = cycle_quantities(record_from_segments(switch))
    assert set(qa) == set(QUANTITIES) and all(np.isfinite(v) for v in qa.values())
    for key in qa:
        assert abs(qb[key] - qa[key]) <= AGREE, (key, qa[key], qb[key])
    assert [s.phase for s in exact] == [s.phase for s in switch]


@pytest.mark.parametrize(
    "changes",
    [{"sigma": 0.3}, {"sigma": 0.5, "belt_deceleration": 0.025}],  # grazing every cycle; belt stops at 20 s
)
def test_affine_trajectory_agrees_with_the_exact_solver(changes):
    exact, switch = both(PAPER_BASELINE.with_(**changes))
    t = np.linspace(0.0, 40.0, 4001)
    xa, va, pa = sample_segments(exact, t)
    xb, vb, pb = sample_segments(switch, t)
    assert np.max(np.abs(xa - xb)) <= AGREE and np.max(np.abs(va - vb)) <= AGREE
    assert np.array_equal(pa, pb)


def test_error_against_the_exact_solver_falls_with_the_tolerance():
    model = BeltModel.build(PAPER_BASELINE.with_(sigma=0.5), "consistent")
    ref = cycle_quantities(record_from_segments(ExactSwitchSolver().segments(model, 30.0)))
    errors = []
    for rtol in (1e-5, 1e-8, 1e-11):
        q = cycle_quantities(record_from_segments(SwitchSolver(rtol=rtol, atol=rtol).segments(model, 30.0)))
        errors.append(max(abs(q[k] - ref[k]) for k in ref))
    assert errors[0] > 10 * errors[1] > 100 * errors[2]


def test_undamped_coulomb_cycle_matches_the_textbook_closed_form():
    p = PAPER_BASELINE.with_(damping=0.0)
    segments = SwitchSolver().segments(LawModel(p, CoulombLaw(0.5, 0.3)), 40.0)
    q = cycle_quantities(record_from_segments(segments))
    cf = coulomb_cycle(p.mass, p.stiffness, p.normal_force, p.belt_velocity, 0.5, 0.3)
    for key in ("period", "stick_duration", "release_position", "onset_position", "x_max", "x_min"):
        assert q[key] == pytest.approx(cf[key], abs=AGREE), key


def test_the_static_limit_decides_stick_or_pass_through():
    p = PAPER_BASELINE.with_(damping=0.0)
    model = LawModel(p, CoulombLaw(0.5, 0.3))
    limit = p.normal_force * 0.5
    x_hold = limit / p.stiffness  # the demand K x (C = 0) at the edge of the static limit
    assert contact_decision(model, 0.0, 0.99 * x_hold) == STICK
    assert contact_decision(model, 0.0, 1.01 * x_hold) == -1  # demand beyond the limit: slips back
    assert contact_decision(model, 0.0, -1.01 * x_hold) == 1
    # Fig. 7 (C = 0.1): the orbit crosses v_r = 0 with |D| > N mu_s, so it passes through without sticking
    fig07 = BeltModel.build(PAPER_BASELINE.with_(sigma=0.5, damping=0.1), "consistent")
    segments = SwitchSolver().segments(fig07, 10)
    passes = [(a, b) for a, b in zip(segments, segments[1:]) if a.phase * b.phase == -1]
    assert passes
    law_model = LawModel.from_belt_model(fig07)
    for a, _ in passes:
        x = float(a.state(a.t1)[0])
        assert abs(float(law_model.stick_demand(a.t1, x))) > law_model.static_force


def test_a_jump_law_sticks_and_every_stick_starts_within_the_static_limit():
    """Coulomb with mu_k < mu_s: the set-valued friction at v_r = 0 catches the mass (|D| <= N mu_s)."""
    p = PAPER_BASELINE.with_(damping=0.5)
    coulomb = SwitchSolver().segments(LawModel(p, CoulombLaw(0.5, 0.2)), 20.0)
    assert any(s.phase == STICK and s.t0 > 0 for s in coulomb)
    for seg in coulomb[1:]:
        if seg.phase == STICK:
            x = float(seg.state(seg.t0)[0])
            assert abs(p.damping * p.belt_velocity + p.stiffness * x) <= p.normal_force * 0.5 + 1e-12


def test_solve_returns_the_common_trajectory_type_with_counters():
    solver = make_solver("switch", rtol=1e-10)
    model = LawModel(PAPER_BASELINE, StribeckLaw(0.5, 0.3, 0.2))
    t = np.linspace(0, 20, 2001)
    traj = solver.solve(model, 20.0, t)
    assert isinstance(traj, Trajectory) and traj.ok and traj.method == "switch"
    assert traj.stats.rhs_evaluations > 0 and traj.stats.events > 0 and traj.stats.steps > 0
    assert traj.segments.shape[1] == 3 and traj.settings["law"]["kind"] == "stribeck"
    stick = traj.phase == STICK
    assert stick.any() and np.allclose(traj.v[stick], traj.belt_velocity[stick], atol=1e-12)
    assert np.all(np.isfinite(traj.x))


def test_bad_settings_and_models_name_the_key():
    with pytest.raises(ParameterError, match="^rtol"):
        SwitchSolver(rtol=float("nan"))
    with pytest.raises(ParameterError, match="^solver settings for 'switch'"):
        make_solver("switch", order=8)
    with pytest.raises(ParameterError, match="^variant"):
        SwitchSolver().solve(BeltModel.build(PAPER_BASELINE, "eq4_printed"), 5.0)
    with pytest.raises(ParameterError, match="^model"):
        SwitchSolver().solve(AffineLaw(0.5, 0.5), 5.0)
