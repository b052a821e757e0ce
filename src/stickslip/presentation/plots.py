"""Figures of the reproduced results (presentation only: reads datasets, draws).

The claims-table helpers the notebooks use live in ``stickslip.presentation.notebook``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

#: What a plot says instead of drawing a failed run (a failed run is never drawn as a result).
FAILED_TEXT = "failed – not a result"

METHOD_STYLE = {"exact": dict(color="C0", lw=1.6), "ode45": dict(color="C3", lw=1.0, ls="--")}


def _draw_run(ax_x, ax_v, ds, method, kind):
    """One method's run: x and v over time (``timeseries``), v over time (``velocity``) or v over x
    (``phase``)."""
    style = METHOD_STYLE.get(method, dict(lw=1.0, ls=":"))
    if kind == "timeseries":
        ax_x.plot(ds.time, ds.displacement, label=method, **style)
    if kind in ("timeseries", "velocity"):
        ax_v.plot(ds.time, ds.velocity, label=method, **style)
    else:
        ax_x.plot(ds.displacement, ds.velocity, label=method, **style)


def _belt_velocity(ax, ds):
    ax.plot(ds.time, ds.belt_velocity, color="0.5", lw=0.8, label="belt velocity")


def _failed_ticks(ax, x):
    """Failed runs as red ticks on the bottom edge (never drawn as values)."""
    ax.plot(x, np.zeros(len(x)), "|", color="red", ms=12, mew=2, transform=ax.get_xaxis_transform())


def _runs(ax, x, y, ok, label="", **style):
    """The runs that succeeded (``ok``) as a line, its ``label`` counting the failed ones, which are drawn as
    red ticks (never as values)."""
    failed = int((~ok).sum())
    count = f" ({failed} runs failed – not results)" if failed and label else ""
    (line,) = ax.plot(x[ok], y[ok], ".-", label=label + count, **style)
    if failed:
        _failed_ticks(ax, x[~ok])
    return line


def _failed_note(ax, ds, method, row):
    """Red note in place of a failed run's curve: the method, the exact wording, the solver's message."""
    message = ds["solver_status"].attrs.get("message") or ""
    ax.text(
        0.02,
        0.92 - 0.1 * row,
        f"{method}: {FAILED_TEXT}" + (f" ({message})" if message else ""),
        transform=ax.transAxes,
        color="red",
        fontsize=8,
        va="top",
    )


def onedof_figure(datasets: dict, figure, reading: str):
    """Fig. 2-style time series (displacement and velocity), Fig. 8-style velocity or Fig. 3-style phase plot
    (``figure``: the typed ``stickslip.schema.Figure``, its ``plot`` and ``title``), every method overlaid; a
    failed run is written out in red, never drawn."""
    kind = figure.plot
    title = f"{figure.title or ''}\nreading: {reading}"
    if kind == "timeseries":
        fig, (ax_x, ax_v) = plt.subplots(2, 1, sharex=True, figsize=(8, 5.5))
    elif kind == "velocity":
        fig, ax_v = plt.subplots(figsize=(8, 3.8))
        ax_x = ax_v
    else:
        fig, ax_x = plt.subplots(figsize=(6.5, 5.2))
        ax_v = None
    for row, (method, ds) in enumerate(datasets.items()):
        if int(ds["solver_status"]) != 0:
            _failed_note(ax_x, ds, method, row)
            continue
        _draw_run(ax_x, ax_v, ds, method, kind)
    if ax_v is not None:
        _belt_velocity(ax_v, next(iter(datasets.values())))
        ax_v.set_ylabel("velocity dx/dt [mm/s]")
        ax_v.set_xlabel("time [s]")
        ax_v.legend(loc="lower right", fontsize=8)
    if kind == "timeseries":
        ax_x.set_ylabel("displacement x [mm]")
        if ax_x.get_legend_handles_labels()[0]:
            ax_x.legend(loc="upper right", fontsize=8)
    elif kind == "phase":
        ax_x.set_xlabel("displacement x [mm]")
        ax_x.set_ylabel("velocity dx/dt [mm/s]")
        if ax_x.get_legend_handles_labels()[0]:
            ax_x.legend(fontsize=8)
    ax_x.set_title(title, fontsize=10)
    fig.tight_layout()
    return fig


#: Colour of each claim status in tables and charts (amber: the numbers cannot decide).
STATUS_COLOUR = {
    "reproduced": "#c8efc8",
    "deviates": "#f7c6c6",
    "indistinguishable": "#ffd98a",
    "not-comparable": "#e4e4e4",
}


def mark_reported(ax, *, x=None, y=None, label=None, color="k"):
    """Dotted reference line for a number the paper reports."""
    font = dict(fontsize=8, color=color)
    if y is not None:
        ax.axhline(y, color=color, ls=":", lw=1)
        where = dict(xycoords=("axes fraction", "data"), ha="right", va="bottom")
        ax.annotate(label or f"paper: {y:g}", (1.0, y), **where, **font)
    if x is not None:
        ax.axvline(x, color=color, ls=":", lw=1)
        where = dict(xycoords=("data", "axes fraction"), ha="left", va="top", rotation=90)
        ax.annotate(label or f"paper: {x:g}", (x, 1.0), **where, **font)


def eq6_figure(ds):
    """Fig. 4: Eq. 6 as printed and the dimensionally correct 1-DOF amplitude curve, peaks marked."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    f = ds.frequency.values
    for var, peak_f, peak_a, style in (
        ("amplitude_printed", "peak_frequency_printed", "peak_amplitude_printed", "C0"),
        ("amplitude_correct", "peak_frequency_correct", "peak_amplitude_correct", "C2"),
    ):
        ax.plot(f, ds[var], color=style, label=ds[var].attrs["long_name"])
        ax.plot(
            float(ds[peak_f]),
            float(ds[peak_a]),
            "o",
            color=style,
            label=f"peak {float(ds[peak_f]):.3f} Hz, {float(ds[peak_a]):.3f} mm",
        )
    ax.plot(0.33, 1.85, "kx", ms=9, label="paper: 0.33 Hz, 1.85 mm")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("amplitude (peak-zero) [mm]")
    ax.set_title(f"Fig. 4: Eq. 6, F = {float(ds.force):g} N (mu_s N)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


SWEEP_METRICS = (
    ("frequency_peaks", "frequency [Hz]"),
    ("amplitude_peak_to_peak", "x peak-peak [mm]"),
    ("amplitude_peak_to_zero", "x peak-zero [mm]"),
    ("stick_fraction", "stick / slip fraction"),
)


def sweep_figure(paper, dense, title: str, reading: str):
    """Figs. 10-14: time series at the paper's values (left) and the dense sweep's metrics (right)."""
    param = paper.attrs["sweep_parameter"]
    fig = plt.figure(figsize=(12, 7))
    gs = fig.add_gridspec(4, 2, width_ratios=[1.4, 1])
    ax_x = fig.add_subplot(gs[:2, 0])
    ax_v = fig.add_subplot(gs[2:, 0], sharex=ax_x)
    for i, value in enumerate(paper[param].values):
        sel = paper.isel({param: i})
        if int(sel.solver_ok) != 1:
            ax_x.text(
                0.02,
                0.92 - 0.08 * i,
                f"{param} = {value:g}: {FAILED_TEXT} ({sel.failure_message.item()})",
                transform=ax_x.transAxes,
                color="red",
                fontsize=7,
            )
            continue
        ax_x.plot(sel.time, sel.displacement, lw=1, label=f"{param} = {value:g}")
        ax_v.plot(sel.time, sel.velocity, lw=1)
    ax_x.set_ylabel("x [mm]")
    ax_v.set_ylabel("dx/dt [mm/s]")
    ax_v.set_xlabel("time [s]")
    ax_x.legend(fontsize=7, loc="upper right")
    ax_x.set_title(f"{title}\nreading: {reading}", fontsize=10)
    x = dense[param].values
    for row, (var, label) in enumerate(SWEEP_METRICS):
        ax = fig.add_subplot(gs[row, 1])
        ok = dense.solver_ok.values == 1
        ax.plot(x[ok], dense[var].values[ok], ".-", ms=3, lw=0.8, label=var)
        if var == "stick_fraction":
            ax.plot(x[ok], 1 - dense[var].values[ok], ".-", ms=3, lw=0.8, label="slip_fraction")
            ax.legend(fontsize=7)
        for xf in x[~ok]:
            ax.axvline(xf, color="red", alpha=0.15, lw=2)
        ax.set_ylabel(label, fontsize=8)
        if row == len(SWEEP_METRICS) - 1:
            ax.set_xlabel(
                f"{param} [{dense[param].attrs.get('units', '')}] (red bands: failed / diverging runs)",
                fontsize=8,
            )
    fig.tight_layout()
    return fig


def critical_speed_figure(datasets: dict):
    """Continuation over belt speed: stick fraction and amplitude per reading, critical speed marked."""
    fig, (ax_s, ax_a) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for reading, ds in datasets.items():
        vb, ok = ds.belt_velocity.values, ds.solver_ok.values == 1
        line = _runs(ax_s, vb, ds.stick_fraction.values, ok, reading)
        _runs(ax_a, vb, ds.amplitude_peak_to_peak.values, ok, color=line.get_color())
        vc = float(ds.critical_belt_speed)
        if np.isfinite(vc) and vc > 0:
            ax_s.axvline(vc, color=line.get_color(), ls=":", lw=1)
    ax_s.set_xscale("log")
    ax_s.set_ylabel("stick fraction")
    ax_a.set_ylabel("x peak-peak [mm]")
    ax_a.set_xlabel("belt speed V_b [mm/s] (continuation, increasing; red ticks: failed – not a result)")
    ax_s.set_title("critical belt speed (dotted): stick-slip disappears beyond it", fontsize=10)
    ax_s.legend(fontsize=7)
    fig.tight_layout()
    return fig


def dense_map_figure(ds, names, title: str):
    """One colour map per metric of a dense map (a line over a single axis); failed runs (solver_ok != 1)
    are hatched and masked, a missing value (no stick-slip) is light grey."""
    import matplotlib.colors

    ydim, xdim = list(ds.solver_ok.dims)[:2] if ds.solver_ok.ndim >= 2 else (None, ds.solver_ok.dims[0])
    failed = ds.solver_ok.values != 1
    fig, axes = plt.subplots(
        1, len(names), figsize=(4.6 * len(names), 4.0), squeeze=False, constrained_layout=True
    )
    for ax, name in zip(axes[0], names):
        if name not in ds:
            raise KeyError(
                f"dense_map plot: {name!r} is not a metric of the map (have {sorted(ds.data_vars)})"
            )
        var = ds[name]
        data = np.ma.masked_where(failed | ~np.isfinite(var.values), var.values)
        x = ds[xdim].values
        if ydim is None:
            ax.plot(x, data, "k.-")
            ax.set_ylabel(f"{var.long_name} [{var.units}]")
        else:
            # Colour limits from the 1st-99th percentile: a few runaway runs (the linear friction law changes
            # sign for |v_r| > 1/sigma) would otherwise flatten the map; arrows on the colour bar mark them.
            values = data.compressed()
            vmin, vmax = np.percentile(values, [1, 99]) if values.size else (0.0, 1.0)
            below = bool(values.size and values.min() < vmin)
            above = bool(values.size and values.max() > vmax)
            extend = "both" if below and above else "min" if below else "max" if above else "neither"
            norm = matplotlib.colors.Normalize(vmin, vmax)
            if values.size and values.min() > 0 and values.max() > 1e3 * values.min():  # spans decades
                norm, extend = matplotlib.colors.LogNorm(values.min(), values.max()), "neither"
            mesh = ax.pcolormesh(x, ds[ydim].values, data, shading="nearest", cmap="viridis", norm=norm)
            mesh.cmap.set_bad("0.85")  # no value (failed run, or no stick-slip): light grey
            fig.colorbar(mesh, ax=ax, label=f"[{var.units}]", extend=extend)
            ax.set_ylabel(f"{ds[ydim].long_name} [{ds[ydim].units}]")
            if failed.any():
                ax.contourf(
                    x, ds[ydim].values, failed.astype(float), levels=[0.5, 1.5], colors="none", hatches=["xx"]
                )
        ax.set_xlabel(f"{ds[xdim].long_name} [{ds[xdim].units}]")
        ax.set_title(var.long_name, fontsize=9)
    fig.suptitle(f"{title}\n{int(failed.sum())} failed runs masked (hatched); grey = no value", fontsize=10)
    return fig


# -- presentation helpers for the comparison notebooks -------------------------------------------------


def metric_units(name: str) -> str:
    """A registered metric's units as a reader writes them (mm/s for the UDUNITS mm s-1)."""
    from ..analysis.metrics import METRICS

    return METRICS[name].units.replace(" s-1", "/s") if name in METRICS else ""


def run_failed(ds) -> bool:
    """True when the dataset's solver failed (its curves must never be drawn as a result)."""
    if "solver_ok" in ds and ds["solver_ok"].ndim == 0:
        return int(ds["solver_ok"]) != 1
    return int(ds["solver_status"]) != 0


def reading_colours(readings):
    """One fixed colour per reading, the same in every panel of a notebook."""
    return {r: f"C{i % 10}" for i, r in enumerate(readings)}


def scalars_vs_reported(datasets: dict, quantities, *, title="", ncols=None):
    """One panel per reported quantity: the measured value of each reading (coloured dot) against the paper's
    number (dotted line, grey band = the claim's tolerance when given). `quantities` is a list of dicts with
    keys var, reported, label and optionally unit (default: the metric registry's), tol_rel / tol_abs and
    ref_label (the reference line's text). A failed run is written out, not drawn; a NaN (nothing to
    measure, e.g. no stick in a reading that never sticks) is written as 'n/a'."""
    readings = list(datasets)
    colours = reading_colours(readings)
    n = len(quantities)
    ncols = ncols or min(n, 4)
    nrows = -(-n // ncols)
    fig, axes = plt.subplots(
        nrows, ncols, figsize=(3.4 * ncols, 0.32 * len(readings) + 2.2 * nrows), squeeze=False
    )
    for ax, q in zip(axes.flat, quantities):
        ypos = np.arange(len(readings))
        for i, r in enumerate(readings):
            failed = run_failed(datasets[r])
            value = float("nan") if failed else float(datasets[r][q["var"]])
            if np.isfinite(value):
                ax.plot(value, i, "o", color=colours[r])
                ax.annotate(f"{value:.3g}", (value, i), xytext=(5, 3), textcoords="offset points", fontsize=7)
            else:  # written out at the left edge
                text, colour = (FAILED_TEXT, "red") if failed else ("n/a (nothing to measure)", "0.4")
                ax.annotate(
                    text, (0.02, i), xycoords=("axes fraction", "data"), color=colour, fontsize=7, va="center"
                )
        rep = q.get("reported")
        if rep is not None:
            ax.axvline(rep, color="k", ls=":", lw=1.2)
            tol = q.get("tol_rel", 0) * abs(rep) + q.get("tol_abs", 0)
            if tol:
                ax.axvspan(rep - tol, rep + tol, color="0.85", zorder=0)
            ax.annotate(
                q.get("ref_label", f"paper: {rep:.4g}"),
                (rep, 1.0),
                xycoords=("data", "axes fraction"),
                fontsize=8,
                ha="left",
                va="bottom",
            )
        ax.set_yticks(ypos, readings, fontsize=7)
        ax.set_ylim(-0.7, len(readings) - 0.3)
        ax.invert_yaxis()
        ax.set_xlabel(f"{q['label']} [{q.get('unit') or metric_units(q['var'])}]", fontsize=8)
        ax.tick_params(axis="x", labelsize=7)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def sweep_metrics_vs_reported(datasets: dict, metrics, reported=(), *, title=""):
    """Dense sweep metrics per reading (one panel per metric) with the paper's numbers as black crosses.

    `datasets` maps reading -> dense sweep dataset; `metrics` is a list of (variable, axis label);
    `reported` is a list of (variable, x, y, label). Failed or diverging runs are not drawn as values: they
    are marked by red ticks on the bottom edge and counted in the legend."""
    readings = list(datasets)
    colours = reading_colours(readings)
    first = next(iter(datasets.values()))
    param = first.attrs["sweep_parameter"]
    fig, axes = plt.subplots(1, len(metrics), figsize=(3.6 * len(metrics), 3.2), squeeze=False)
    for ax, (var, label) in zip(axes[0], metrics):
        for r, ds in datasets.items():
            _runs(
                ax,
                ds[param].values,
                ds[var].values,
                ds.solver_ok.values == 1,
                r,
                ms=3,
                lw=0.9,
                color=colours[r],
            )
        for rvar, rx, ry, rlabel in reported:
            if rvar == var:
                ax.plot([rx], [ry], "x", color="k", ms=9, mew=2, zorder=5, label=None)  # the paper's number
                ax.annotate(rlabel, (rx, ry), xytext=(4, 4), textcoords="offset points", fontsize=7)
        units = first[param].attrs.get("units", "")
        ax.set_xlabel(f"{param} [{units}]", fontsize=8)
        ax.set_ylabel(label, fontsize=8)
    axes[0, 0].legend(fontsize=6)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def readings_grid(datasets: dict, kind="timeseries", *, title="", marks=None):
    """One row (time series: x and v side by side) or one panel (velocity, phase) per reading, every method
    of the reading overlaid; failed runs are written out in red instead of drawn. `datasets` maps
    reading -> {method: dataset}. `marks` is a list of dicts passed to `mark_reported` on every x panel
    (time series), v panel (velocity) or phase panel, keyed by 'on': 'x' | 'v' | 'phase'."""
    readings = list(datasets)
    marks = marks or []
    if kind == "timeseries":
        fig, axes = plt.subplots(
            len(readings), 2, figsize=(12, 2.2 * len(readings)), sharex=True, squeeze=False
        )
        panels = [(row[0], row[1]) for row in axes]
    else:
        ncols = min(len(readings), 2 if kind == "velocity" else 3)
        nrows = -(-len(readings) // ncols)
        size = (6 * ncols, 2.6 * nrows) if kind == "velocity" else (4.2 * ncols, 3.6 * nrows)
        fig, axes = plt.subplots(nrows, ncols, figsize=size, squeeze=False)
        panels = [(ax, None) for ax in axes.flat]
        for ax in list(axes.flat)[len(readings) :]:
            ax.set_visible(False)
    for (ax_a, ax_b), reading in zip(panels, readings):
        for i, (method, ds) in enumerate(datasets[reading].items()):
            if run_failed(ds):
                message = ds["solver_status"].attrs.get("message", "")
                for y, text, size in (
                    (0.92 - 0.09 * (2 * i), f"{method}: {FAILED_TEXT}", 8),
                    (0.83 - 0.18 * i, message[:60], 7),
                ):
                    ax_a.text(0.02, y, text, transform=ax_a.transAxes, color="red", fontsize=size, va="top")
                continue
            _draw_run(ax_a, ax_a if ax_b is None else ax_b, ds, method, kind)
        if kind in ("timeseries", "velocity"):
            ax_v = ax_a if ax_b is None else ax_b
            _belt_velocity(ax_v, next(iter(datasets[reading].values())))
            ax_v.set_ylabel("dx/dt [mm/s]", fontsize=8)
            if kind == "timeseries":
                ax_a.set_ylabel(f"{reading}\nx [mm]", fontsize=8)
            else:
                ax_a.set_title(reading, fontsize=9)
        else:
            ax_a.set_title(reading, fontsize=9)
            ax_a.set_xlabel("x [mm]", fontsize=8)
            ax_a.set_ylabel("dx/dt [mm/s]", fontsize=8)
        targets = {"timeseries": {"x": ax_a, "v": ax_b}, "velocity": {"v": ax_a}, "phase": {"phase": ax_a}}
        for m in marks:
            if m.get("on", "x") not in ("x", "v", "phase"):
                raise KeyError(m["on"])
            if (target := targets[kind].get(m.get("on", "x"))) is not None:
                mark_reported(target, **{k: v for k, v in m.items() if k != "on"})
    if kind in ("timeseries", "velocity"):
        for ax in axes[-1]:
            ax.set_xlabel("time [s]")
        axes[0, 1 if kind == "timeseries" else 0].legend(fontsize=7, loc="upper right")
    else:
        with_lines = [ax for ax in axes.flat if ax.get_legend_handles_labels()[0]]
        if with_lines:
            with_lines[0].legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig
