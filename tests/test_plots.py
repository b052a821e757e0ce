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
