"""Every FE default has one home: each public entry point, run with its defaults, does what the config's
schema and config/fe.yaml say a value left out means (issue 39: the safety factor, the start, the binning,
the peer, the stability cross-checks and the 1-DOF sample count were once written in several places)."""

import inspect

import numpy as np
import pytest
import yaml

from stickslip.fe import params as fe_params
from stickslip.fe.continuum import build_continuum, increments, integrate_continuum, stable_time_step
from stickslip.fe.explicit import integrate
from stickslip.fe.scene import build_scene
from stickslip.schema.fe import DEFAULT_BIN_WIDTH, FeOutput, FePeer, FeScene, Stability

from project_run import ROOT

FE_YAML = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]
BEAM, DISC = fe_params.BeamParams(n_elements=4), fe_params.DiscParams(surface_speed_mm_s=0.5)
CONTACT, FRICTION = fe_params.ContactParams(), fe_params.FrictionTable((0.0,), (0.4,))


def test_the_solver_defaults_are_the_configs_and_every_integrator_runs_with_them():
    """The scenes' solver, the run settings both integrators check, their signatures and config/fe.yaml's
    fe.defaults.solver: one safety factor and one start. Run with their defaults, the beam and the
    continuum step at that factor times their stable step."""
    solver = FE_YAML["defaults"]["solver"]
    defaults = fe_params.SolverParams()
    assert defaults.safety_factor == solver["safety_factor"] == fe_params.DEFAULT_SAFETY_FACTOR
    assert defaults.initial_state == solver["initial_state"] == fe_params.DEFAULT_INITIAL_STATE
    settings = fe_params.run_settings(1e-5)
    assert settings.safety_factor == defaults.safety_factor
    assert settings.initial_state == defaults.initial_state
    for entry in (integrate, integrate_continuum, increments, fe_params.run_settings):
        signature = inspect.signature(entry).parameters
        assert signature["safety_factor"].default == defaults.safety_factor, entry.__name__
        if "initial_state" in signature:
            assert signature["initial_state"].default == defaults.initial_state, entry.__name__
    strip = build_continuum(BEAM, DISC, CONTACT, FRICTION, nx=4, ny=1)
    continuum = integrate_continuum(strip, 1e-5)
    assert continuum.dt == pytest.approx(defaults.safety_factor * stable_time_step(strip), rel=1e-12)
    assert continuum.extra["initial_state"] == defaults.initial_state
    beam = build_scene(fe_params.SceneParams(BEAM, DISC, CONTACT, defaults), FRICTION)
    run = integrate(beam.system, beam.law, 1e-5)
    assert run.dt == pytest.approx(defaults.safety_factor * run.dt_crit, rel=1e-12)
    given = integrate(beam.system, beam.law, 1e-5, initial_state=defaults.initial_state)
    assert np.array_equal(run.x, given.x) and np.array_equal(run.normal_force, given.normal_force)
    n = increments(strip, 1e-5)
    assert n == int(np.ceil(1e-5 / (defaults.safety_factor * stable_time_step(strip)) - 1e-9))


def test_the_schemas_defaults_are_what_config_fe_yaml_writes_out():
    """A key the config may leave out: its schema default equals the value config/fe.yaml gives anyway."""
    assert FeScene().output == FeOutput() and FeOutput().bin_width == DEFAULT_BIN_WIDTH
    assert DEFAULT_BIN_WIDTH == FE_YAML["defaults"]["output"]["bin_width"]
    assert FePeer().model_dump() == FE_YAML["peer"]
    stability = Stability.model_validate({"base": "s", "angles": [0.0], "slopes": [0.0]})
    given = FE_YAML["stability"]
    assert stability.crosscheck_e_folds == given["crosscheck_e_folds"]
    assert stability.crosscheck_max_t_end == given["crosscheck_max_t_end"]


def test_the_one_dof_sample_count_has_one_home():
    """A 1-DOF run without sample times, and the divergence guard's record of a run that failed, both
    sample ``DEFAULT_SAMPLES`` times."""
    from stickslip.analysis.divergence import BoundedSolver
    from stickslip.model import BeltModel, BeltParams
    from stickslip.solvers.base import DEFAULT_SAMPLES, default_t_eval

    class Failing:
        name, settings = "failing", {}

        def solve(self, model, t_end, t_eval=None):
            raise ValueError("no step")

    assert default_t_eval(2.0).size == DEFAULT_SAMPLES
    p = BeltParams(mass=1, stiffness=5, damping=1.5, mu_s=0.5, sigma=0.5, normal_force=10, belt_velocity=0.5)
    failed = BoundedSolver(Failing(), transient=1.0).solve(BeltModel.build(p, "consistent"), 2.0)
    assert failed.stats.status == "failed" and failed.t.size == DEFAULT_SAMPLES
