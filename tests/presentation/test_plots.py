"""Figures draw from datasets (presentation code is still code): what is plotted is the data, failed runs are
written out, never drawn."""


def _run_dataset(**changes):
    import numpy as np

    from stickslip.io.netcdf import trajectory_dataset
    from stickslip.model import PAPER_BASELINE, BeltModel
    from stickslip.solvers import make_solver

    model = BeltModel.build(PAPER_BASELINE.with_(**changes), "consistent")
    t = np.linspace(0.0, 10.0, 501)
    return trajectory_dataset(make_solver("exact").solve(model, 10.0, t))


def _figure(**plot):
    """A figure of the config as the rules hand it on (``stickslip.schema.Figure``); its default plot kind."""
    from stickslip.schema import Figure

    return Figure(title="t", scene="fig02", readings=["r"], methods=["exact"], **plot)


def test_onedof_figure_draws_the_datasets_samples():
    """The time-series figure plots exactly the dataset's displacement and velocity against its time, and
    the phase plot velocity against displacement - not a resampled or rescaled copy."""
    import matplotlib

    matplotlib.use("Agg")
    import numpy as np

    from stickslip.presentation.plots import onedof_figure

    ds = _run_dataset()
    fig = onedof_figure({"exact": ds}, _figure(plot="timeseries"), reading="consistent_caption")
    ax_x, ax_v = fig.axes
    np.testing.assert_array_equal(ax_x.lines[0].get_xdata(), ds.time.values)
    np.testing.assert_array_equal(ax_x.lines[0].get_ydata(), ds.displacement.values)
    np.testing.assert_array_equal(ax_v.lines[0].get_ydata(), ds.velocity.values)
    np.testing.assert_array_equal(ax_v.lines[-1].get_ydata(), ds.belt_velocity.values)  # the belt
    phase = onedof_figure({"exact": ds}, _figure(plot="phase"), reading="consistent_caption")
    np.testing.assert_array_equal(phase.axes[0].lines[0].get_xdata(), ds.displacement.values)
    np.testing.assert_array_equal(phase.axes[0].lines[0].get_ydata(), ds.velocity.values)


def test_a_failed_run_is_written_out_not_drawn():
    import matplotlib

    matplotlib.use("Agg")

    from stickslip.presentation.plots import onedof_figure

    ds = _run_dataset()
    failed = ds.copy()
    failed["solver_status"] = failed["solver_status"] * 0 + 1
    failed["solver_status"].attrs["message"] = "budget: more than 100000 RHS evaluations"
    fig = onedof_figure({"exact": ds, "ode45": failed}, _figure(), reading="r")
    ax_x = fig.axes[0]
    assert len(ax_x.lines) == 1  # only the successful run is drawn
    assert any("ode45" in t.get_text() and "100000" in t.get_text() for t in ax_x.texts)
