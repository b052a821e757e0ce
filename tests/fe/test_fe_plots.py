"""The FE figures draw from the datasets the pipeline writes (envelopes + full-resolution windows)."""

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from stickslip.fe.params import FrictionTable  # noqa: E402
from stickslip.presentation.fe_plots import fe_readings_figure, fe_scene_figure  # noqa: E402
from stickslip.studies.fe import result_dataset, scene_dataset  # noqa: E402

MAPPING = {
    "beam": {"n_elements": 6},
    "disc": {"surface_speed_mm_s": 0.5},
    "solver": {"t_end": 0.004, "initial_state": "drop", "output_dt": 2.5e-6},
    "output": {"bin_width": 2e-4, "windows": [[0.0, 0.001], [0.003, 0.004]]},
}


@pytest.fixture(scope="module")
def ds():
    return scene_dataset(MAPPING, FrictionTable.paper_fig17(), "tiny")


def test_dataset_keeps_full_resolution_only_in_windows(ds):
    t = ds.time.values
    assert ((t <= 0.001 + 1e-12) | (t >= 0.003 - 1e-12)).all()
    dt = float(ds.time_step)
    assert np.median(np.diff(t[t < 0.001])) == pytest.approx(dt * max(1, round(2.5e-6 / dt)), rel=1e-9)
    # bins cover the whole run; per-bin state fractions add up to one
    edges = ds.bin_time.values[[0, -1]] + np.array([-1e-4, 1e-4])
    assert edges[0] == pytest.approx(0.0, abs=1e-15) and edges[1] >= t[-1]
    total = sum(ds[f"{k}_fraction_per_bin"].values for k in ("stick", "slip", "separation"))
    np.testing.assert_allclose(total, 1.0)


def test_binned_envelope_bounds_the_samples(ds):
    t = ds.time.values
    x = ds.horizontal_displacement.values
    idx = np.clip(np.searchsorted(ds.bin_time.values - 1e-4, t, side="right") - 1, 0, ds.bin_time.size - 1)
    assert (x >= ds.horizontal_displacement_min.values[idx] - 1e-18).all()
    assert (x <= ds.horizontal_displacement_max.values[idx] + 1e-18).all()


def test_scene_and_readings_figures_draw(ds):
    fig = fe_scene_figure(ds, ds, reported={"max": 2.9e-4})
    assert len(fig.axes) == 9  # u, v, du/dt, dv/dt, states, spectrum, forces, two windows
    assert any(np.allclose(line.get_ydata(), 2.9e-4) for line in fig.axes[0].get_lines())  # paper, in mm
    assert "[mm/s]" in fig.axes[2].get_ylabel() and "[mm]" in fig.axes[0].get_ylabel()
    fig2 = fe_readings_figure({("a", "tiny"): ds, ("b", "tiny"): ds}, ["tiny"], ["a", "b"])
    assert len(fig2.axes) == 5


def test_result_dataset_windows_default_to_start_and_end(ds):
    from stickslip.studies.fe import run_scene

    r, m, _ = run_scene(MAPPING, FrictionTable.paper_fig17())
    d = result_dataset(r, m)
    half = r.t[-1] / 2  # a 4 ms run: the 5 ms default span is cut to half the run
    np.testing.assert_allclose(d.detail_windows.values, [[0.0, half], [half, r.t[-1]]])
