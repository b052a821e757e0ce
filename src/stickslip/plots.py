"""Figures of the reproduced results (presentation only: reads datasets, draws)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

METHOD_STYLE = {"exact": dict(color="C0", lw=1.6), "ode45": dict(color="C3", lw=1.0, ls="--")}


def _style(method):
    return METHOD_STYLE.get(method, dict(lw=1.0, ls=":"))


def _label(ds, method):
    failed = int(ds["solver_status"]) != 0
    return f"{method}" + (" (FAILED: not a result)" if failed else "")


def onedof_figure(datasets: dict, spec: dict, reading: str):
    """Fig. 2-style time series (displacement and velocity) or Fig. 3-style phase plot."""
    kind = spec.get("plot", "timeseries")
    title = f"{spec.get('title', '')} [reading: {reading}]"
    if kind == "timeseries":
        fig, (ax_x, ax_v) = plt.subplots(2, 1, sharex=True, figsize=(8, 5.5))
        for method, ds in datasets.items():
            if int(ds["solver_status"]) != 0:
                ax_x.text(
                    0.02,
                    0.9 - 0.1 * list(datasets).index(method),
                    f"{method}: solver failed ({ds['solver_status'].attrs.get('message')}) - not a result",
                    transform=ax_x.transAxes,
                    color="red",
                )
                continue
            ax_x.plot(ds.time, ds.displacement, label=_label(ds, method), **_style(method))
            ax_v.plot(ds.time, ds.velocity, label=_label(ds, method), **_style(method))
        ds0 = next(iter(datasets.values()))
        ax_v.plot(ds0.time, ds0.belt_velocity, color="0.5", lw=0.8, label="belt velocity")
        ax_x.set_ylabel("displacement x [mm]")
        ax_v.set_ylabel("velocity dx/dt [mm/s]")
        ax_v.set_xlabel("time [s]")
        ax_x.legend(loc="upper right", fontsize=8)
        ax_v.legend(loc="lower right", fontsize=8)
        ax_x.set_title(title, fontsize=10)
    elif kind == "velocity":
        fig, ax_v = plt.subplots(figsize=(8, 3.5))
        for method, ds in datasets.items():
            if int(ds["solver_status"]) != 0:
                ax_v.text(
                    0.02,
                    0.9 - 0.1 * list(datasets).index(method),
                    f"{method}: solver failed ({ds['solver_status'].attrs.get('message')}) - not a result",
                    transform=ax_v.transAxes,
                    color="red",
                    fontsize=8,
                )
                continue
            ax_v.plot(ds.time, ds.velocity, label=_label(ds, method), **_style(method))
        ds0 = next(iter(datasets.values()))
        ax_v.plot(ds0.time, ds0.belt_velocity, color="0.5", lw=0.8, label="belt velocity")
        ax_v.set_ylabel("velocity dx/dt [mm/s]")
        ax_v.set_xlabel("time [s]")
        ax_v.legend(loc="lower right", fontsize=8)
        ax_v.set_title(title, fontsize=10)
    elif kind == "phase":
        fig, ax = plt.subplots(figsize=(6, 5))
        for i, (method, ds) in enumerate(datasets.items()):
            if int(ds["solver_status"]) != 0:
                ax.text(
                    0.02,
                    0.9 - 0.1 * i,
                    f"{method}: solver failed ({ds['solver_status'].attrs.get('message')}) - not a result",
                    transform=ax.transAxes,
                    color="red",
                    fontsize=8,
                )
                continue
            ax.plot(ds.displacement, ds.velocity, label=_label(ds, method), **_style(method))
        ax.set_xlabel("displacement x [mm]")
        ax.set_ylabel("velocity dx/dt [mm/s]")
        ax.legend(fontsize=8)
        ax.set_title(title, fontsize=10)
    else:
        raise ValueError(f"plot: {kind!r} is not one of ['timeseries', 'velocity', 'phase']")
    fig.tight_layout()
    return fig


STATUS_COLOUR = {"reproduced": "#c8efc8", "deviates": "#f7c6c6", "not-comparable": "#e4e4e4"}


def claims_frame(csv_path, sections=None, claims=None):
    """The deviations table (optionally filtered) as a pandas DataFrame."""
    import pandas as pd

    frame = pd.read_csv(csv_path, dtype={"section": str}).fillna({"reading": "-"})
    if sections is not None:
        frame = frame[frame["section"].isin([str(s) for s in sections])]
    if claims is not None:
        frame = frame[frame["claim"].isin(claims)]
    return frame


def styled_claims(frame):
    """Colour each status cell; a status that differs from its pin is marked in bold red text."""
    cols = [
        "claim",
        "reading",
        "figure",
        "quantity",
        "reported",
        "measured",
        "unit",
        "deviation",
        "status",
        "expected",
        "reason",
    ]

    def colour(row):
        styles = [""] * len(row)
        i = list(row.index).index("status")
        styles[i] = f"background-color: {STATUS_COLOUR.get(row['status'], 'white')}"
        if row["status"] != row["expected"]:
            styles[i] += "; color: red; font-weight: bold"
        return styles

    return (
        frame[cols]
        .style.apply(colour, axis=1)
        .format({"reported": "{:.4g}", "measured": "{:.4g}", "deviation": "{:+.1%}"}, na_rep="–")
        .hide(axis="index")
    )


def status_counts(frame):
    """Claims per reading and status: the compact scoreboard of a section."""
    return frame.pivot_table(index="reading", columns="status", values="claim", aggfunc="count", fill_value=0)


def mark_reported(ax, *, x=None, y=None, label=None, color="k"):
    """Dotted reference line for a number the paper reports."""
    if y is not None:
        ax.axhline(y, color=color, ls=":", lw=1)
        ax.annotate(
            label or f"paper: {y:g}",
            (1.0, y),
            xycoords=("axes fraction", "data"),
            ha="right",
            va="bottom",
            fontsize=8,
            color=color,
        )
    if x is not None:
        ax.axvline(x, color=color, ls=":", lw=1)
        ax.annotate(
            label or f"paper: {x:g}",
            (x, 1.0),
            xycoords=("data", "axes fraction"),
            ha="left",
            va="top",
            fontsize=8,
            color=color,
            rotation=90,
        )


FE_PANELS = (
    (("horizontal_displacement", "vertical_displacement"), "displacement of node 1 [mm]"),
    (("horizontal_velocity", "vertical_velocity"), "velocity of node 1 [mm/s]"),
    (("normal_force", "friction_force"), "contact force [N]"),
    (("contact_state",), "contact state"),
)


def fe_scene_figure(ds, periods: int = 6):
    """Whole run (left) and a zoom on the last few periods of the dominant frequency (right).

    The beam vibrates at kHz for a second, so the whole-run panel only shows the envelope; the zoom shows
    the stick/slip/separation pattern itself.
    """
    t = ds.time.values
    f_dom = float(ds["dominant_frequency"]) if "dominant_frequency" in ds else float("nan")
    span = periods / f_dom if f_dom > 0 else (t[-1] - t[0]) / 50
    zoom = t >= t[-1] - span
    fig, axes = plt.subplots(
        len(FE_PANELS), 2, figsize=(12, 9), sharex="col", gridspec_kw={"width_ratios": [2, 1]}
    )
    for row, (names, label) in zip(axes, FE_PANELS):
        for name in names:
            if name not in ds:
                continue
            units = ds[name].attrs.get("units", "")
            row[0].plot(t, ds[name].values, lw=0.5, label=f"{name} [{units}]")
            row[1].plot(t[zoom], ds[name].values[zoom], lw=0.9, label=name)
        row[0].set_ylabel(label, fontsize=8)
        row[0].legend(fontsize=7, loc="upper right")
    if "contact_state" in ds:
        meanings = ds["contact_state"].attrs.get("flag_meanings", "")
        axes[-1, 0].set_title(f"flags: {meanings}", fontsize=8)
    axes[-1, 0].set_xlabel("time [s]")
    axes[-1, 1].set_xlabel(f"time [s] (last {periods} periods of {f_dom:.4g} Hz)")
    fig.suptitle(ds.attrs.get("title", ""), fontsize=10)
    fig.tight_layout()
    return fig


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
                f"{param} = {value:g}: run failed ({sel.failure_message.item()}) - not a result",
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
    ax_x.set_title(f"{title} [reading: {reading}]", fontsize=10)
    x = dense[param].values
    for row, (var, label) in enumerate(SWEEP_METRICS):
        ax = fig.add_subplot(gs[row, 1])
        ok = dense.solver_ok.values == 1
        ax.plot(x[ok], dense[var].values[ok], ".-", ms=3, lw=0.8, label=var)
        if var == "stick_fraction":
            ax.plot(x[ok], 1 - dense[var].values[ok], ".-", ms=3, lw=0.8, label="slip_fraction")
            ax.legend(fontsize=7)
        if (~ok).any():
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
        vb = ds.belt_velocity.values
        ok = ds.solver_ok.values == 1
        (line,) = ax_s.plot(vb[ok], ds.stick_fraction.values[ok], ".-", label=reading)
        ax_a.plot(vb[ok], ds.amplitude_peak_to_peak.values[ok], ".-", color=line.get_color())
        vc = float(ds.critical_belt_speed)
        if np.isfinite(vc):
            ax_s.axvline(vc, color=line.get_color(), ls=":", lw=1)
    ax_s.set_xscale("log")
    ax_s.set_ylabel("stick fraction")
    ax_a.set_ylabel("x peak-peak [mm]")
    ax_a.set_xlabel("belt speed V_b [mm/s] (continuation, increasing)")
    ax_s.legend(fontsize=7)
    fig.tight_layout()
    return fig
