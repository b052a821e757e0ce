"""Figures draw from datasets (presentation code is still code)."""

import numpy as np


def test_fe_scene_figure_draws_a_dataset():
    import matplotlib

    matplotlib.use("Agg")
    import xarray as xr

    from stickslip.plots import fe_scene_figure

    t = np.linspace(0, 1e-3, 101)
    ds = xr.Dataset(
        {
            "horizontal_displacement": ("time", np.sin(2e4 * t), {"units": "mm"}),
            "contact_state": (
                "time",
                np.ones_like(t),
                {"units": "1", "flag_meanings": "separated stick slip"},
            ),
            "dominant_frequency": ((), 3183.0),
        },
        coords={"time": t},
    )
    fig = fe_scene_figure(ds)
    assert fig is not None and len(fig.axes) == 8


def test_moved_notebook_helpers_still_import_from_plots():
    """Notebooks written for the old layout (``from stickslip.plots import claims_frame``) keep working."""
    import pytest

    from stickslip import notebook, plots
    from stickslip.plots import claims_frame, reported_value, status_counts, styled_claims

    assert claims_frame is notebook.claims_frame and styled_claims is notebook.styled_claims
    assert status_counts is notebook.status_counts and reported_value is notebook.reported_value
    assert plots.claims_readings is notebook.claims_readings
    with pytest.raises(AttributeError, match="no_such_helper"):
        plots.no_such_helper  # noqa: B018
