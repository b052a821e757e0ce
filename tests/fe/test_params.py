"""The FE parameters' defaults: one home each (stickslip.fe.params)."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_every_explicit_entry_point_starts_and_steps_as_the_config_default_does():
    """One default each for the start and the step factor: the scenes' solver, both integrators, the cost
    guard's estimate and config/fe.yaml's fe.defaults.solver agree."""
    import inspect

    import yaml

    from stickslip.fe import params as fe_params
    from stickslip.fe.continuum import increments, integrate_continuum
    from stickslip.fe.explicit import integrate

    solver = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]["defaults"]["solver"]
    defaults = fe_params.SolverParams()
    assert defaults.initial_state == solver["initial_state"] == fe_params.DEFAULT_INITIAL_STATE
    assert defaults.safety_factor == solver["safety_factor"] == fe_params.DEFAULT_SAFETY_FACTOR
    for entry in (integrate, integrate_continuum, increments):
        signature = inspect.signature(entry).parameters
        assert signature["safety_factor"].default == fe_params.DEFAULT_SAFETY_FACTOR, entry.__name__
        if "initial_state" in signature:
            assert signature["initial_state"].default == fe_params.DEFAULT_INITIAL_STATE, entry.__name__
