"""The one stepping contract (``solvers.base.OneDofSolver``): every registered method is one, owns no
``solve()`` of its own, refuses bad settings when it is built (naming the setting), and turns a run that
cannot proceed into a failed trajectory the same way."""

import numpy as np
import pytest

from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.model.params import ParameterError
from stickslip.solvers import METHODS, REGISTRY, SolverError, make_solver
from stickslip.solvers.base import OneDofSolver


@pytest.fixture(scope="module")
def model():
    return BeltModel.build(PAPER_BASELINE.with_(sigma=0.5), "consistent")


@pytest.mark.parametrize("name", sorted(REGISTRY))
def test_every_method_is_the_contract_and_leaves_solve_to_it(name):
    cls = METHODS[name]
    assert issubclass(cls, OneDofSolver)
    own_solve = [c.__name__ for c in cls.__mro__ if c is not OneDofSolver and "solve" in vars(c)]
    assert own_solve == [], f"{name}: solve() overridden in {own_solve}"


@pytest.mark.parametrize("name", sorted(REGISTRY))
def test_default_settings_are_accepted(name):
    assert make_solver(name).settings


BAD_SETTINGS = [
    ("moreau", {"theta": 0.0}, "theta"),
    ("moreau", {"theta": 1.5}, "theta"),
    ("moreau", {"h": -1e-3}, "h"),
    ("moreau", {"max_steps": 0}, "max_steps"),
    ("sign_rk", {"rtol": -1e-3}, "rtol"),
    ("sign_rk", {"atol": 0.0}, "atol"),
    ("sign_rk", {"rtol": True}, "rtol"),
    ("sign_rk", {"max_step": float("nan")}, "max_step"),
    ("sign_rk", {"method": "Euler"}, "method"),
    ("smooth", {"eps": 0.0}, "eps"),
    ("smooth", {"regularization": "erf"}, "regularization"),
    ("smooth", {"stick_tolerance": -1.0}, "stick_tolerance"),
    ("karnopp", {"eta": -1.0}, "eta"),
    ("exact", {"samples_per_period": 0}, "samples_per_period"),
    ("exact", {"graze_tolerance": -1e-12}, "graze_tolerance"),
    ("switch", {"rtol": float("nan")}, "rtol"),
    ("switch", {"method": "BDF"}, "method"),
    ("switch", {"max_segments": 2.5}, "max_segments"),
]


@pytest.mark.parametrize("name, bad, key", BAD_SETTINGS)
def test_bad_settings_raise_at_construction_naming_the_setting(name, bad, key):
    with pytest.raises(ParameterError, match=rf"^{key}: "):
        METHODS[name](**bad)  # the constructor itself, before any solve
    with pytest.raises(ParameterError, match=rf"^solver settings for {name!r}: {key}: "):
        make_solver(name, **bad)


def test_moreau_refuses_explicit_smooth_forces_as_the_config_check_does():
    """theta = 0 is outside (0, 1]: refused when the solver is built, by the same check the config uses."""
    with pytest.raises(ValueError, match=r"^theta: input should be greater than 0, got 0.0$"):
        METHODS["moreau"](h=1e-3, theta=0.0)


@pytest.mark.parametrize("name", sorted(REGISTRY))
@pytest.mark.parametrize("t_end", [0.0, -1.0, float("nan"), "x"])
def test_bad_t_end_is_an_error_for_every_method(model, name, t_end):
    with pytest.raises(SolverError, match=rf"^{name} solver: t_end"):
        make_solver(name).solve(model, t_end)


@pytest.mark.parametrize(
    "name, limit, segments",
    [
        ("exact", {"max_segments": 3}, (0, 3)),
        ("switch", {"max_segments": 3}, (0, 3)),
        ("moreau", {"max_steps": 10}, None),
    ],
)
def test_a_run_that_cannot_proceed_is_a_failed_trajectory(model, name, limit, segments):
    t_eval = np.linspace(0.0, 40.0, 81)
    tr = make_solver(name, **limit).solve(model, 40.0, t_eval)
    assert tr.stats.status == "failed" and tr.stats.failures == 1 and tr.stats.message
    assert np.all(np.isnan(tr.x)) and np.all(np.isnan(tr.v)) and not tr.phase.any()
    assert np.array_equal(tr.t, t_eval) and np.array_equal(tr.belt_velocity, model.belt_velocity(t_eval))
    assert (tr.segments is None) if segments is None else (tr.segments.shape == segments)
    assert tr.method == make_solver(name).solve(model, 1.0).method  # stored under the method's own label


@pytest.mark.parametrize("name", sorted(REGISTRY))
def test_default_output_times_and_counters(model, name):
    tr = make_solver(name).solve(model, 4.0)
    assert tr.ok and np.array_equal(tr.t, np.linspace(0.0, 4.0, 2001))
    assert tr.stats.steps > 0 and tr.stats.cpu_time >= 0.0
