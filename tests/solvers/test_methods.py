"""The alternative methods behind the common interface, the work budget, and the error/failure measures."""

import numpy as np
import pytest

from stickslip.analysis.errors import compare, cycle_metrics, segment_cycle_metrics, state_error
from stickslip.analysis.failure import belt_position, classify
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import STICK, make_solver
from stickslip.solvers.budget import run_with_budget

T_END = 12.0
T_EVAL = np.linspace(0.0, T_END, 1201)


def scene(variant="consistent", **changes):
    return BeltModel.build(PAPER_BASELINE.with_(**changes), variant)


@pytest.fixture(scope="module")
def base():
    model = scene(sigma=0.5)
    exact = make_solver("exact")
    ref = exact.solve(model, T_END, T_EVAL)
    return model, ref, segment_cycle_metrics(exact.segments(model, 60.0))


@pytest.mark.parametrize(
    "name, settings, tol",
    [
        ("smooth", {"eps": 1e-5, "method": "Radau"}, 5e-3),
        (
            "smooth",
            {"eps": 1e-6, "regularization": "arctan", "method": "LSODA", "rtol": 1e-8, "atol": 1e-11},
            5e-2,
        ),
        ("karnopp", {"eta": 1e-4}, 2e-3),
        ("moreau", {"h": 1e-3, "theta": 0.5}, 1e-4),
    ],
)
def test_methods_converge_to_the_exact_solution(base, name, settings, tol):
    model, ref, _ = base
    tr = make_solver(name, **settings).solve(model, T_END, T_EVAL)
    assert tr.ok, tr.stats.message
    assert state_error(tr, ref)["state"] < tol
    assert tr.stats.rhs_evaluations > 0


def observed_orders(model, ref, theta, steps):
    """log2 of successive error ratios for halved step sizes: the observed convergence order."""
    errs = [
        state_error(make_solver("moreau", h=h, theta=theta).solve(model, T_END, T_EVAL), ref)["state"]
        for h in steps
    ]
    return np.log2(np.array(errs[:-1]) / np.array(errs[1:]))


def test_moreau_sticks_exactly(base):
    model, _, _ = base
    tr = make_solver("moreau", h=1e-3).solve(model, T_END, T_EVAL)
    stick = tr.phase == STICK
    assert stick.any() and np.all(tr.v[stick] == tr.belt_velocity[stick])


def test_moreau_backward_euler_is_first_order_and_midpoint_about_second(base):
    """Observed orders against the exact solution, step halved each time: theta = 1 (backward Euler) is first
    order; theta = 1/2 is close to second order despite the stick/slip switches (mean >= 1.5)."""
    model, ref, _ = base
    first = observed_orders(model, ref, 1.0, (4e-3, 2e-3, 1e-3))
    assert np.all(np.abs(first - 1.0) < 0.1), first
    midpoint = observed_orders(model, ref, 0.5, (2e-3, 1e-3, 5e-4))
    assert np.mean(midpoint) >= 1.5 and np.all(midpoint > 1.2), midpoint


def test_karnopp_creep_is_bounded_by_the_band(base):
    model, ref, _ = base
    eta = 1e-3
    tr = make_solver("karnopp", eta=eta).solve(model, T_END, T_EVAL)
    f = classify(tr, ref, model.params)
    assert 0 < f["creep_mm"] <= eta * 1.7 + 1e-12  # first stick lasts 1.7 s


def test_sign_rk_loose_tolerance_misses_stick(base):
    model, ref, _ = base
    tr = make_solver("sign_rk", rtol=1e-2, atol=1e-5).solve(model, T_END, T_EVAL)
    assert classify(tr, ref, model.params)["failure_kind"] == "missed_stick"


def test_smooth_large_eps_creeps(base):
    model, ref, _ = base
    tr = make_solver("smooth", eps=1e-2).solve(model, T_END, T_EVAL)
    f = classify(tr, ref, model.params)
    assert f["creep"] and f["failure_kind"] == "creep"


def test_budget_turns_a_stall_into_data(base):
    model, ref, _ = base
    tr = run_with_budget(make_solver("sign_rk", rtol=1e-8, atol=1e-11), model, T_END, T_EVAL, max_rhs=20_000)
    assert tr.stats.status == "failed" and "budget" in tr.stats.message
    assert np.all(np.isnan(tr.x))
    f = classify(tr, ref, model.params)
    assert f["failure_kind"] == "step_collapse"
    assert compare(tr, ref)["state"] == np.inf


def test_exact_is_its_own_reference(base):
    model, ref, ref_cycle = base
    c = compare(ref, ref, ref_cycle)
    assert c["state"] == 0.0
    assert c["period_error"] < 1e-8 and c["amplitude_error"] < 1e-8  # sampled cycle vs closed form
    assert classify(ref, ref, model.params)["failure_kind"] == "none"


def test_cycle_metrics_of_a_sine():
    t = np.linspace(0, 20, 2001)
    c = cycle_metrics(t, 0.7 * np.sin(2 * t), 1.4 * np.cos(2 * t))
    assert c["period"] == pytest.approx(np.pi, rel=1e-7) and c["amplitude"] == pytest.approx(1.4, rel=1e-7)


def test_belt_position_decelerating():
    p = PAPER_BASELINE.with_(belt_deceleration=0.025)
    assert belt_position(p, 20.0) == pytest.approx(5.0) and belt_position(p, 40.0) == pytest.approx(5.0)


def test_moreau_handles_printed_and_decelerating_scenes():
    tr = make_solver("moreau", h=1e-3).solve(scene("eq3_printed", sigma=0.5), 10.0, np.linspace(0, 10, 101))
    assert tr.ok and not np.any(tr.phase == STICK)
    tr = make_solver("moreau", h=1e-3).solve(
        scene(sigma=0.5, belt_deceleration=0.025), 30.0, np.linspace(0, 30, 301)
    )
    assert tr.ok and np.all(tr.v[tr.t > 21] == 0.0)


def test_stall_budget_counts_rhs_evaluations_of_adaptive_methods_only():
    """The methods study's budget is a count (the same on every machine), and a fixed-step method, whose
    work t_end / h is known before it runs, is never stopped by it."""
    from stickslip.pipeline.config import load_config
    from stickslip.schema import Budget, MethodsStudy, Timing
    from stickslip.studies.methods import run_scene

    from project_run import ROOT

    small = load_config([ROOT / "config/methods.yaml", ROOT / "config/test/methods.yaml"])["methods_study"]
    study = MethodsStudy.model_validate(small).model_copy(
        update={
            "output_dt": 0.05,
            "budget": Budget(max_rhs=3000, max_cpu=60.0),
            "timing": Timing(min_repeats=1, max_repeats=1, min_total_cpu=0.0),
        }
    )
    methods = [
        ("moreau", {"h": 1e-3}, "moreau h=1e-3"),  # 10 000 steps
        ("sign_rk", {"method": "RK45", "rtol": 1e-5, "atol": 1e-8}, "chattering RK45"),
    ]
    records, *_ = run_scene(study, scene(), 10.0, methods, paper=False)
    moreau, rk = records
    assert moreau["status"] == "ok" and moreau["rhs_evaluations"] >= 10_000
    assert rk["status"] == "failed" and rk["rhs_evaluations"] == 3001 and "3000 RHS" in rk["message"]
