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


def test_both_integrators_and_the_figures_read_a_start_the_same_way():
    """One reading of ``initial_state``: the alias ``undeformed`` is ``drop``, a missing value the default
    (a figure read a dataset without one as ``static`` before), anything else refused naming the key by
    the beam integrator and the continuum alike."""
    import numpy as np
    import pytest

    from stickslip.fe import params as fe_params
    from stickslip.fe.continuum import build_continuum, integrate_continuum
    from stickslip.fe.explicit import integrate

    assert fe_params.initial_state_of(None) == fe_params.DEFAULT_INITIAL_STATE
    assert fe_params.initial_state_of("undeformed") == "drop"
    assert fe_params.initial_state_of("static") == "static"
    from stickslip.fe.scene import build_scene

    beam, disc = fe_params.BeamParams(n_elements=4), fe_params.DiscParams(surface_speed_mm_s=0.5)
    contact, friction = fe_params.ContactParams(), fe_params.FrictionTable((0.0,), (0.4,))
    scene = build_continuum(beam, disc, contact, friction, nx=4, ny=1)
    built = build_scene(fe_params.SceneParams(beam, disc, contact, fe_params.SolverParams()), friction)
    messages = []
    for run in (
        lambda: integrate_continuum(scene, 1e-5, initial_state="dropped"),
        lambda: integrate(built.system, built.law, 1e-5, initial_state="dropped"),
    ):
        with pytest.raises(ValueError, match=r"^initial_state: ") as err:
            run()
        messages.append(str(err.value))
    assert messages[0] == messages[1]
    assert np.isfinite(integrate_continuum(scene, 1e-5, initial_state="undeformed").x).all()
    # the deflection figure adds the static shape only to a static start's series
    import json

    import xarray as xr

    from stickslip.presentation.fe_paper_figures import _absolute

    for solver, offset in (
        ({}, 0.0),
        ({"initial_state": "undeformed"}, 0.0),
        ({"initial_state": "static"}, 5.0),
    ):
        ds = xr.Dataset(attrs={"parameters": json.dumps({"solver": solver})})
        assert _absolute(ds, 1.0, 2.0, 5.0)[:2] == (1.0 + offset, 2.0 + offset)
