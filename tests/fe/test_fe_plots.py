"""The FE figures draw from the datasets the pipeline writes (envelopes + full-resolution windows)."""

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
import yaml

matplotlib.use("Agg")

from stickslip.fe.params import FrictionTable  # noqa: E402
from stickslip.presentation.fe_plots import fe_readings_figure, fe_scene_figure  # noqa: E402
from stickslip.studies.fe_packing import result_dataset  # noqa: E402
from stickslip.studies.fe_scene import scene_dataset  # noqa: E402

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
    from stickslip.studies.fe_scene import run_scene

    r, m, _ = run_scene(MAPPING, FrictionTable.paper_fig17())
    d = result_dataset(r, m)
    half = r.t[-1] / 2  # a 4 ms run: the 5 ms default span is cut to half the run
    np.testing.assert_allclose(d.detail_windows.values, [[0.0, half], [half, r.t[-1]]])


# ------------------------------------------------------------------ one figure per paper figure (Figs. 21-36)
from matplotlib.collections import PolyCollection  # noqa: E402

from stickslip.presentation.fe_paper_figures import (  # noqa: E402
    PAPER_FIGURE_NUMBERS,
    TIME_SERIES,
    paper_deflection_figure,
    paper_figure,
    paper_time_series_figure,
)

PAPER_21 = [
    {"label": "max horizontal displacement", "value": 0.00029, "unit": "mm"},
    {"label": "mean horizontal displacement", "value": -0.00015, "unit": "mm"},
    {"label": "max abs horizontal displacement", "value": 0.00029, "unit": "mm"},  # the fitted row's repeat
    {"label": "disc surface speed", "value": 0.5, "unit": "mm s-1"},  # another quantity than the axis
]


def _with(ds, **changes):
    """The dataset with its scene parameters changed (sketches and start state read only ``parameters``)."""
    import json

    out = ds.copy()
    p = json.loads(ds.attrs["parameters"])
    for path, value in changes.items():
        group, key = path.split("__")
        p[group][key] = value
    out.attrs["parameters"] = json.dumps(p)
    return out


def _hlines_at(ax, y):
    return [ln for ln in ax.get_lines() if np.allclose(ln.get_ydata(), y) and np.ptp(ln.get_xdata()) == 1]


def _texts(fig):
    return " ".join(t.get_text() for t in fig.findobj(matplotlib.text.Text))


def test_paper_time_series_has_a_column_per_scene_and_the_papers_lines_in_mm(ds):
    fig = paper_time_series_figure(21, {"a_15p2rpm": ds, "b_0p5mm_s": ds}, PAPER_21)
    assert len(fig.axes) == 2 * 4  # node 1, mid-span, normal force, last window per scene
    for col in (0, 4):
        node1 = fig.axes[col]
        assert "mm]" in node1.get_ylabel() and "µm" not in node1.get_ylabel()
        assert len(_hlines_at(node1, 0.00029)) == 1  # once, though two rows claim it
        assert len(_hlines_at(node1, -0.00015)) == 1
        assert not _hlines_at(node1, 0.5)  # mm/s is not drawn on a displacement axis...
        lo, hi = node1.get_ylim()
        assert lo < -0.00015 and hi > 0.00029  # the paper's lines are inside the axes
    assert "disc surface speed 0.5 mm/s" in _texts(fig)  # ...but listed under the figure
    assert "Fig. 21:" in fig._suptitle.get_text() and "lower_face_drop" in fig._suptitle.get_text()


def test_paper_time_series_draws_the_midspan_node_and_the_normal_force_zero(ds):
    fig = paper_time_series_figure(23, {"a": ds}, [])
    node1, midspan, normal, zoom = fig.axes
    labels = [c.get_label() for c in midspan.collections if isinstance(c, PolyCollection)]
    assert any("mid-span" in lab for lab in labels)
    lo, hi = ds.midspan_vertical_displacement_min.values, ds.midspan_vertical_displacement_max.values
    band = midspan.collections[0].get_paths()[0].vertices[:, 1]
    assert band.min() == pytest.approx(lo.min()) and band.max() == pytest.approx(hi.max())
    assert _hlines_at(normal, 0.0) and "zero" in _hlines_at(normal, 0.0)[0].get_label()
    assert "[N]" in normal.get_ylabel() or "N]" in normal.get_ylabel()
    assert zoom.get_xlim() == pytest.approx(tuple(ds.detail_windows.values[-1]))


def test_paper_velocity_figure_is_in_mm_per_s_with_the_running_envelope(ds):
    assert TIME_SERIES[24].envelope and not TIME_SERIES[24].normal_force
    fig = paper_time_series_figure(24, {"a": ds}, [])
    assert len(fig.axes) == 4  # node 1, mid-span, first-mode growth, last window: no normal force row
    axes = [ax for i, ax in enumerate(fig.axes) if i != 2]  # the growth row (tested below) is relative
    assert all("mm/s]" in ax.get_ylabel() for ax in axes)
    env = [p for p in fig.axes[0].patches if "running envelope" in (p.get_label() or "")]
    withheld = "running envelope: not converged" in _texts(fig)
    assert env or withheld
    if env:  # the staircase is the dataset's half peak-to-peak about the window mean
        top = env[0].get_path().vertices[:, 1]
        assert np.nanmax(top) >= np.nanmax(ds.horizontal_velocity_envelope.values) - 1e-12


def test_every_paper_figure_21_to_36_draws_the_scenes_the_config_names(ds, repo_root):
    figures = yaml.safe_load((repo_root / "config" / "fe.yaml").read_text())["fe"]["paper_figures"]
    stated_first = ["section9_kinematic_15p2rpm", "section9_kinematic_0p5mm_s"]
    assert figures[21] == stated_first  # 15.2 rpm first
    names = sorted({s for scenes in figures.values() for s in scenes})
    dss = {
        n: _with(ds, contact__method="fixed_normal") if n.startswith("section10") else
        _with(ds, contact__angle_deg=30.0) if n.startswith("section12") else ds
        for n in names
    }  # fmt: skip
    for number in PAPER_FIGURE_NUMBERS:
        fig = paper_figure(number, {s: dss[s] for s in figures[number]}, several_times=3.0)
        assert fig._suptitle.get_text().startswith(f"Fig. {number}:")
        plt.close(fig)


def test_mode_shape_figure_labels_modes_with_their_frequency(ds):
    fig = paper_figure(22, {"section9_a": ds})
    static, modes = fig.axes
    labels = [ln.get_label() for ln in modes.get_lines() if "Hz" in ln.get_label()]
    assert len(labels) >= 3
    f1 = ds.natural_frequency.values[0]
    assert any(f"{f1:.0f} Hz" in lab for lab in labels)
    assert any(np.allclose(ln.get_ydata(), ds.static_deflection_vertical.values) for ln in static.get_lines())


def _bar(ax, x):
    """The y range of the range bar drawn at x (a thick vertical line)."""
    bars = [ln for ln in ax.get_lines() if ln.get_linewidth() == 5 and np.allclose(ln.get_xdata(), x)]
    assert len(bars) == 1, f"one bar at x = {x}"
    return np.asarray(bars[0].get_ydata())


def test_deflection_figure_bars_span_the_runs_vertical_range(ds):
    fig = paper_deflection_figure({"section11_a": ds}, several_times=3.0)
    beam, force = fig.axes
    length = float(ds.node_position.values[-1])
    tip = _bar(beam, length)
    assert tip.min() == pytest.approx(float(ds.vertical_displacement_min.min()))  # drop start: absolute
    assert tip.max() == pytest.approx(float(ds.vertical_displacement_max.max()))
    assert _bar(beam, length / 2).min() == pytest.approx(float(ds.midspan_vertical_displacement_min.min()))
    assert _hlines_at(force, 0.0) and _hlines_at(force, 3.0)  # zero and the paper's "several times"
    # a static start measures from the static shape: the bars then add it
    static = _with(ds, solver__initial_state="static")
    fig = paper_deflection_figure({"section11_a": static})
    mid = float(np.interp(length / 2, ds.node_position.values, ds.static_deflection_vertical.values))
    assert _bar(fig.axes[0], length / 2).min() == pytest.approx(
        float(ds.midspan_vertical_displacement_min.min()) + mid
    )


def test_boundary_sketches_follow_the_scene_parameters(ds):
    fig = paper_figure(26, {"section10_x_0p5mm_s": _with(ds, contact__method="fixed_normal")})
    assert "upper face held vertically" in _texts(fig)
    assert fig.axes[0].get_aspect() == 1.0  # to scale
    fig = paper_figure(34, {"section12_x": _with(ds, contact__angle_deg=30.0)})
    assert "30°" in _texts(fig) and "upper face held" not in _texts(fig)
    disc = [p for p in fig.axes[0].patches if isinstance(p, matplotlib.patches.Circle) and p.radius == 12.5]
    assert disc and disc[0].center[0] == pytest.approx(100 + 12.5 * np.sin(np.radians(30)))


def test_scene_figure_draws_the_comparison_over_the_continuums_window(ds):
    short = ds.sel(bin_time=ds.bin_time[ds.bin_time <= 0.002], time=ds.time[ds.time <= 0.002])
    short["detail_windows"] = (("detail_window", "bound"), np.array([[0.0, 0.001], [0.001, 0.002]]))
    fig = fe_scene_figure(ds, short)
    assert fig.axes[0].get_xlim()[1] < 0.0025  # the beam's 4 ms run is cut at the continuum's 2 ms
    assert fig.axes[1].get_legend() is None  # one legend above the panels, none over the vertical trace


def test_growth_row_draws_the_first_mode_against_the_linear_estimate(ds):
    """Figs. 24, 25, 27, 29 (the paper's "increases"): the first mode's amplitude relative to its first
    window, both step sizes, and e^(lambda t) of the eigen-analysis; the fitted rate and its step-halving
    note printed."""
    t = np.arange(0.025, 1.0, 0.05)
    grown = (
        ds.drop_dims("mode_window", errors="ignore")
        .assign(
            first_mode_amplitude=("mode_window", 2e-5 * np.exp(0.5 * t)),
            first_mode_amplitude_half_step=("mode_window", 2e-5 * np.exp(0.48 * t)),
            first_mode_growth_rate=(
                (),
                0.5,
                {"step_halving": "sign converged, value moves 4.0 % at half step"},
            ),
            first_mode_growth_rate_linear=0.36,
            first_mode_frequency=366.2,
        )
        .assign_coords(mode_window_time=("mode_window", t))
    )
    assert all(TIME_SERIES[n].growth for n in (24, 25, 27, 29))
    fig = paper_time_series_figure(24, {"a": grown}, [])
    growth = fig.axes[2]
    lines = {line.get_label(): line for line in growth.get_lines()}
    measured = lines["first mode (366.2 Hz), node 1, dt"].get_ydata()
    np.testing.assert_allclose(measured, np.exp(0.5 * (t - t[0])))
    linear = next(v for k, v in lines.items() if k.startswith("linear estimate +0.36"))
    np.testing.assert_allclose(linear.get_ydata(), np.exp(0.36 * (t - t[0])))
    assert "at dt/2" in lines
    assert "fitted over the leading segment: +0.5 1/s (sign converged" in _texts(fig)


def _scaled(ds, factor):
    """The dataset with every displacement and force series scaled by ``factor`` (another magnitude)."""
    out = ds.copy()
    for name in list(ds.data_vars):
        if name.startswith(("horizontal_displacement", "normal_force")) and ds[name].dtype.kind == "f":
            out[name] = ds[name] * factor
    return out


@pytest.mark.parametrize("number", [21, 29])
def test_every_column_of_a_row_draws_its_quantity_in_one_unit(ds, number):
    """Columns whose data differ 1000-fold still share the row's power of ten (the larger one's), so a
    tick reads the same in every column; the tick labels are the values divided by that power."""
    fig = paper_time_series_figure(number, {"large": ds, "small": _scaled(ds, 1e-3)}, [])
    n_rows = len(fig.axes) // 2
    left, right = fig.axes[:n_rows], fig.axes[n_rows:]
    for a, b in zip(left, right):
        assert a.get_ylabel() == b.get_ylabel()
    node1 = left[0]
    label = node1.get_ylabel()
    e = int(label.split("10^{")[1].split("}")[0]) if "10^{" in label else 0
    top = max(abs(v) for v in node1.get_ylim())
    assert e < -2 and 1 <= top / 10.0**e < 10  # the larger column sets the power (1e-4 mm here)
    for ax in (node1, right[0]):
        tick = ax.get_yticks()[-1]
        assert ax.yaxis.get_major_formatter()(tick, 0) == f"{tick / 10.0**e:g}"


def test_fig29_draws_the_papers_times_and_the_zero_line(ds):
    spec = TIME_SERIES[29]
    reported = [{"label": "stick end time", "value": 0.6, "unit": "s"}]
    fig = paper_time_series_figure(29, {"a": ds}, reported)
    node1 = fig.axes[0]
    assert _hlines_at(node1, 0.0) and spec.zero_line in _texts(fig)
    # the 4 ms test run ends before the paper's times: listed under the figure, not drawn off the axes
    text = _texts(fig)
    assert "stick end time at 0.6 s (after the end of this run)" in text
    assert "the jump at 0.85 s (after the end of this run)" in text
    # a run that reaches them draws both as vertical lines on every whole-run panel of the column
    fig, ax = plt.subplots(2)
    from stickslip.presentation.fe_paper_figures import _paper_times, _time_lines

    times = _paper_times(spec, reported)
    assert times == [(0.6, "stick end time"), (0.85, "the jump")]
    assert _time_lines(list(ax), times, t_end=1.0) == set()
    for a in ax:
        assert sorted(ln.get_xdata()[0] for ln in a.get_lines()) == [0.6, 0.85]


def test_fig23_states_the_papers_comparison_with_the_runs_values(ds):
    fig = paper_time_series_figure(23, {"a": ds}, [])
    text = _texts(fig)
    assert "paper: the vertical amplitude is higher than the horizontal" in text
    v, h = float(ds["vertical_amplitude"]), float(ds["horizontal_amplitude"])
    assert f"vertical amplitude {v:.3g} mm vs horizontal amplitude {h:.3g} mm" in text
    assert ("so it holds here" in text) == (v > h)
    withheld = ds.copy()
    withheld["vertical_amplitude"] = withheld["vertical_amplitude"] * np.nan  # as step halving withholds it
    text = _texts(paper_time_series_figure(23, {"a": withheld}, []))
    assert "vertical amplitude withheld" in text and "not decided" in text and "nan" not in text
