"""How the FE parameters read a run's start (stickslip.fe.params; their defaults: test_defaults.py)."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


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
