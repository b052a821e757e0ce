"""One figure per paper figure of the beam-on-disc sections (Figs. 21-36), to lay beside the paper's.

Presentation only: every curve is read from the scene datasets the pipeline writes. Time series are drawn as
the paper draws them (node 1 over the whole run, in mm and mm/s), as the min-max band per pixel column (never
the raw samples: a 12.9 kHz chatter over 1 s is 400 000 points), with the same quantity at the mid-span node
(off the contact), a sample-by-sample zoom of the last full-resolution window with the contact state shaded,
and, where the paper's claim is separation, the normal force with its zero line. The paper's numbers come in
from the claims rows (the rule's params) and are drawn as labelled horizontal lines.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Arc, Circle, FancyArrowPatch, Rectangle

from .. import catalogue as paths
from ..fe.params import initial_state_of
from .fe_plots import (
    NOTE_BOX,
    PAPER_COLOUR,
    axes_note,
    band_columns,
    detail_window,
    envelope_windows,
    grouped,
    paper_line,
    power_of_ten,
    scaled_ylabel,
    sci_ticks,
    shade_states,
    state_legend_handles,
)

#: the running mean drawn over the band averages this many seconds (several periods of the 366 Hz mode)
MEAN_SPAN = 0.01
UNIT_LABEL = {"mm": "mm", "mm s-1": "mm/s"}
QUANTITY = {
    "horizontal_displacement": ("horizontal displacement u", "mm"),
    "vertical_displacement": ("vertical displacement v", "mm"),
    "horizontal_velocity": ("horizontal velocity du/dt", "mm s-1"),
    "vertical_velocity": ("vertical velocity dv/dt", "mm s-1"),
}


@dataclass(frozen=True)
class PaperFigure:
    """What one paper time-series figure shows."""

    variable: str  #: node-1 series (QUANTITY key)
    caption: str  #: the paper's caption, shortened
    envelope: bool = False  #: the paper claims the quantity "increases": draw the running envelope
    normal_force: bool = False  #: the paper's claim is separation: draw the normal force and its zero
    #: the paper claims self-excited growth: draw the first mode's amplitude against the linear estimate
    growth: bool = False
    #: times [s] the paper's text names for this figure, with what happens then (drawn as vertical lines
    #: beside any time its claims rows give in s)
    times: tuple = ()
    #: the paper says node 1 oscillates about zero: draw the zero line on node 1's panel
    zero_line: str = ""
    #: the paper's statement comparing two of the dataset's scalars: (text, lhs variable, rhs variable)
    statement: tuple = ()


TIME_SERIES = {
    21: PaperFigure(
        "horizontal_displacement",
        "Displacement (mm) at beam node 1 in horizontal direction",
        normal_force=True,
    ),
    23: PaperFigure(
        "vertical_displacement",
        "Vertical displacement of beam at node 1",
        normal_force=True,
        statement=(
            "paper: the vertical amplitude is higher than the horizontal (Fig. 23 against Fig. 21)",
            "vertical_amplitude",
            "horizontal_amplitude",
        ),
    ),
    24: PaperFigure("horizontal_velocity", "Horizontal velocity at beam node 1", envelope=True, growth=True),
    25: PaperFigure(
        "vertical_velocity", "Vertical velocity versus time of beam at node 1", envelope=True, growth=True
    ),
    27: PaperFigure(
        "horizontal_displacement",
        "Horizontal displacement of the beam at node 1 (upper face held)",
        envelope=True,
        growth=True,
    ),
    28: PaperFigure("horizontal_velocity", "Horizontal velocity for the beam at node 1 (upper face held)"),
    29: PaperFigure(
        "horizontal_displacement",
        "Horizontal displacements versus time at beam node 1 (penalty)",
        normal_force=True,
        growth=True,
        times=((0.85, "the jump"),),  # "oscillate at its natural frequency at 0.85 second"
        zero_line="paper: oscillates about its equilibrium position (0.0, 0.0)",
    ),
    30: PaperFigure(
        "vertical_displacement",
        "Vertical displacement at node 1 for the beam (penalty)",
        normal_force=True,
    ),
    32: PaperFigure("horizontal_velocity", "Horizontal velocity for the beam at node 1 (penalty)"),
    33: PaperFigure(
        "vertical_velocity", "Vertical velocity versus time at node 1 (penalty)", normal_force=True
    ),
    35: PaperFigure(
        "horizontal_displacement", "Horizontal displacements for the beam at node 1 (contact at 30°)"
    ),
    36: PaperFigure("horizontal_velocity", "Horizontal velocity for the beam at node 1 (contact at 30°)"),
}
PAPER_FIGURE_NUMBERS = tuple(paths.fe_paper_figure_numbers())  # one home: the catalogue
#: how the sketches name each contact method (stickslip.fe.params.ContactParams.method)
METHOD_NOTE = {
    "kinematic": "kinematic contact (exact\nnon-penetration, may separate)",
    "penalty": "penalty contact",
    "fixed_normal": "normal force held at the\nstatic value (no separation)",
}


def distinct_values(rows) -> list[dict]:
    """The paper's numbers for one figure (``{label, value, unit}`` rows from its claims), once per value and
    unit, labelled by the first row: the fitted-setup rows and the second disc speed repeat the forward rows'
    numbers."""
    out = {}
    for r in rows:
        out.setdefault((float(r["value"]), r["unit"]), r)
    return list(out.values())


# ----------------------------------------------------------------------------------------------- helpers
def _mean_span(ds, span=MEAN_SPAN) -> float:
    """Averaging span of the running mean: a whole number of periods of the dominant frequency (so the
    bending ring averages out instead of beating), at most ``span``."""
    f = float(ds["dominant_frequency"]) if "dominant_frequency" in ds else float("nan")
    if np.isfinite(f) and f > 1.0 / span:
        return np.floor(span * f) / f
    return span


def _running_mean(ds, var, span=MEAN_SPAN):
    t = ds.bin_time.values
    dt = float(np.median(np.diff(t))) if t.size > 1 else span
    k = max(1, int(round(_mean_span(ds, span) / dt)))
    m = t.size // k * k  # whole groups only: a last group of a few bins would show its ripple
    if k == 1 or m == 0:
        return t, ds[f"{var}_mean"].values
    return grouped(t[:m], k, np.nanmean), grouped(ds[f"{var}_mean"].values[:m], k, np.nanmean)


def _band(ax, ds, var, colour, label, mean=True):
    t, lo, hi = band_columns(ds, var)
    width = float(np.median(np.diff(t))) * 1e3 if t.size > 1 else 0.0
    ax.fill_between(t, lo, hi, color=colour, alpha=0.45, lw=0, label=f"{label}: min-max per {width:.2g} ms")
    if mean:
        tm, mm = _running_mean(ds, var)
        span = _mean_span(ds) * 1e3
        ax.plot(tm, mm, color="k", lw=0.9, label=f"mean per {span:.3g} ms")
    if float(np.nanmax(np.abs(hi))) == 0.0 and float(np.nanmax(np.abs(lo))) == 0.0:
        axes_note(
            ax, 0.5, 0.5, "identically zero (held by the constraint)", ha="center", va="bottom", color="0.3"
        )


def _envelope(ax, ds, var, colour):
    """The running envelope a growth claim is judged on (half peak-to-peak per window, ``<var>_envelope``)
    drawn +- about each window's mean, as a staircase over the windows."""
    if (found := envelope_windows(ds, var)) is None:
        return
    tw, env, w = found
    if not np.isfinite(env.values).any():
        why = env.attrs.get("step_halving", "")
        note = "not converged under step halving" if why.startswith("not converged") else "not in the dataset"
        axes_note(
            ax, 0.01, 0.97, f"running envelope: {note} (withheld)", va="top", color=colour, bbox=NOTE_BOX
        )
        return
    env = env.values
    tb, mb = ds.bin_time.values, ds[f"{var}_mean"].values
    centre = np.array([np.nanmean(mb[(tb >= a - w / 2) & (tb < a + w / 2)]) for a in tw])
    edges = np.concatenate([tw - w / 2, [tw[-1] + w / 2]])
    for sgn, label in ((1, f"running envelope: ± half peak-to-peak per {w:.2g} s"), (-1, None)):
        ax.stairs(centre + sgn * env, edges, baseline=None, color=colour, lw=1.6, ls="--", label=label)


def _disc_speed(ds) -> tuple:
    """(rev/min where the scene states it, else None; surface speed [mm/s]) of the scene's disc."""
    rev = json.loads(ds.attrs.get("parameters", "{}")).get("disc", {}).get("speed_rev_per_min")
    return rev, float(ds["disc_surface_speed"]) if "disc_surface_speed" in ds else float("nan")


def _speed_label(ds) -> str:
    rev, v = _disc_speed(ds)
    return f"disc {rev:g} rev/min = {v:.3g} mm/s at the surface" if rev else f"disc surface {v:.3g} mm/s"


#: a legend in a row of its own above its panel
ABOVE = dict(fontsize=7, loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False, borderaxespad=0.1)


def _legend_above(ax, ncol=4, **kw):
    ax.legend(**kw, **ABOVE, ncol=ncol)


def _title(number, caption, scenes, reading, width=110):
    head, tail = f"Fig. {number}: {caption}", f"{', '.join(scenes)}, FE reading {reading}"
    return f"{head} — {tail}" if len(head) + len(tail) < width else f"{head} —\n{tail}"


# ------------------------------------------------------------------------------------ time-series figures
def paper_time_series_figure(number: int, datasets: dict, reported=(), reading: str = "lower_face_drop"):
    """Paper Fig. ``number`` (a TIME_SERIES key): one column per scene (``datasets``: name -> dataset),
    rows: node 1 over the whole run (band, running mean, the running envelope where the paper claims growth,
    the paper's numbers as labelled lines), the mid-span node, the normal force with its zero line (where
    the claim is separation) and the last full-resolution window sample by sample with the contact state.
    ``reported``: the paper's numbers for this figure, ``{label, value, unit}`` with unit mm or mm s-1 (from
    its claims rows); those in another unit than the panel's are listed under the figure."""
    spec = TIME_SERIES[number]
    reported = distinct_values(reported)
    times = _paper_times(spec, reported)
    reported = [r for r in reported if r["unit"] != "s"]
    what, unit = QUANTITY[spec.variable]
    ulab = UNIT_LABEL[unit]
    short = f"{what.split()[0]} {what.split()[-1]}"
    rows = (
        ["node1", "midspan"] + (["normal"] if spec.normal_force else []) + (["growth"] if spec.growth else [])
    )
    rows += ["zoom"]
    heights = {"node1": 3.0, "midspan": 2.0, "normal": 1.7, "growth": 2.2, "zoom": 2.2}
    ncol = len(datasets)
    height = 1.6 + 0.55 * len(rows) + sum(heights[r] for r in rows)
    fig = plt.figure(figsize=(6.5 * ncol + 0.5, height))
    gs = fig.add_gridspec(
        len(rows),
        ncol,
        height_ratios=[heights[r] for r in rows],
        hspace=0.62,
        wspace=0.2,
        left=0.07,
        right=0.985,
        top=1 - 1.45 / height,
        bottom=0.75 / height,
    )
    labelled = {}  # row -> [(axes, label, unit)] over the columns: one unit per row
    beyond = set()
    for j, (scene, ds) in enumerate(datasets.items()):
        axes = {}
        for i, r in enumerate(rows):
            axes[r] = fig.add_subplot(
                gs[i, j], sharex=axes.get("node1") if r in ("midspan", "normal") else None
            )
        dt_bin = float(np.median(np.diff(ds.bin_time.values))) if ds.bin_time.size > 1 else 0.0
        t_end = float(ds.bin_time.values[-1]) + dt_bin / 2
        ax = axes["node1"]
        _band(ax, ds, spec.variable, "C0", "node 1 (contact)")
        if spec.envelope:
            _envelope(ax, ds, spec.variable, "C1")
        for r in reported:
            if r["unit"] == unit:
                paper_line(ax, r["value"], f"paper: {r['label']} {r['value']:g} {UNIT_LABEL[unit]}")
        if spec.zero_line:
            paper_line(ax, 0.0, spec.zero_line, ls="-.", lw=1.1, x=0.01)
        if spec.statement:
            _statement(ax, ds, *spec.statement)
        ax.set_title(f"{scene}: {_speed_label(ds)}", fontsize=9, pad=30 if spec.envelope else 19)
        _legend_above(ax, ncol=2 if spec.envelope else 3)
        _band(axes["midspan"], ds, f"midspan_{spec.variable}", "C2", "mid-span node (off the contact)")
        if j == 0:  # the rows below node 1 draw the same things in every column: one legend per row
            _legend_above(axes["midspan"], ncol=2)
        if "normal" in axes:
            ax = axes["normal"]
            _band(ax, ds, "normal_force", "C4", "normal force", mean=False)
            ax.axhline(0.0, color=PAPER_COLOUR, lw=1.0, label="zero: separated below")
            if "static_normal_force" in ds:
                ax.axhline(
                    float(ds["static_normal_force"]), color="0.2", ls=":", lw=1.2, label="static N (weight)"
                )
            if j == 0:
                _legend_above(ax, ncol=3)
        if "growth" in axes:
            _first_mode_growth(axes["growth"], ds, legend=j == 0)
            axes["growth"].set_xlim(0.0, t_end)
        for r, label, u in (
            ("node1", f"{short}\nnode 1", ulab),
            ("midspan", f"{short}\nmid-span", ulab),
            ("normal", "normal force", "N"),
        ):
            if r in axes:
                axes[r].set_xlim(0.0, t_end)
                axes[r].grid(alpha=0.25)
                axes[r].tick_params(labelsize=8)
                labelled.setdefault(r, []).append((axes[r], label, u))
        beyond |= _time_lines(
            [axes[r] for r in ("node1", "midspan", "normal", "growth") if r in axes], times, t_end
        )
        axes["normal" if "normal" in axes else "midspan"].set_xlabel("time [s] (whole run)", fontsize=8)
        ax = axes["zoom"]
        t0, t1, m = detail_window(ds, -1)
        t = ds.time.values[m]
        y = ds[spec.variable].values[m]
        base, label = 0.0, f"{short}\nnode 1"
        # a ripple on a large offset (the held section 10 scene): draw the ripple about a rounded mean
        if y.size and np.ptp(y) < 1e-3 * abs(float(np.mean(y))):
            base = float(f"{np.mean(y):.3g}")
            label = f"{short} node 1\n− {base:g} {ulab}"
        ax.plot(t, y - base, color="C0", lw=0.7, label="node 1, every sample")
        if y.size and float(np.nanmax(np.abs(y))) < 1e-13:  # round-off: the node is held by the contact
            note = "round-off level only: node 1 is held on the disc"
            axes_note(ax, 0.5, 0.03, note, ha="center", color="0.2", bbox=NOTE_BOX)
        ax.set_xlim(t0, t1)
        shade_states(ax, t, ds.contact_state.values[m], alpha=0.2)
        ax.set_xlabel(
            f"time [s]: last full-resolution window, {t0:.4g}-{t1:.4g} s (shading: contact state)", fontsize=8
        )
        ax.tick_params(labelsize=8)
        labelled.setdefault("zoom", []).append((ax, label, ulab))
        if j == 0:
            _legend_above(ax, handles=ax.get_lines()[:1] + state_legend_handles(alpha=0.2))
    for row in labelled.values():  # the same power of ten in every column of a row (one unit per quantity)
        e = power_of_ten([ax for ax, _, _ in row])
        for ax, label, u in row:
            scaled_ylabel(ax, label, u, exponent=e)
    other = [f"{r['label']} {r['value']:g} {UNIT_LABEL[r['unit']]}" for r in reported if r["unit"] != unit]
    other += [f"{label} at {t:g} s (after the end of this run)" for t, label in sorted(beyond)]
    if other:
        text = "; ".join(other)
        fig.text(
            0.01,
            0.01,
            f"Also claimed for Fig. {number} (another quantity, not on these axes): {text}",
            fontsize=8,
            color=PAPER_COLOUR,
            va="bottom",
        )
    fig.suptitle(_title(number, spec.caption, list(datasets), reading), fontsize=11)
    return fig


def _paper_times(spec: PaperFigure, reported) -> list[tuple[float, str]]:
    """(time [s], what happens then) the paper names for a figure: from its claims rows in s, then the
    ones its text alone gives (``PaperFigure.times``), each time once."""
    out = {float(r["value"]): r["label"] for r in reported if r["unit"] == "s"}
    for t, label in spec.times:
        out.setdefault(float(t), label)
    return sorted(out.items())


def _time_lines(axes, times, t_end) -> set:
    """The paper's times as vertical lines on every panel of a column, labelled on the first; returns
    those after ``t_end`` (the run ended before them: listed under the figure instead)."""
    beyond = set()
    for t, label in times:
        if t > t_end:
            beyond.add((t, label))
            continue
        for i, ax in enumerate(axes):
            ax.axvline(t, color=PAPER_COLOUR, ls=":", lw=1.3)
            if i == 0:
                ax.annotate(
                    f"paper: {label} ({t:g} s)",
                    (t, 0.02),
                    xycoords=("data", "axes fraction"),
                    xytext=(-3, 0),
                    textcoords="offset points",
                    rotation=90,
                    ha="right",
                    va="bottom",
                    fontsize=7.5,
                    color=PAPER_COLOUR,
                    bbox={**NOTE_BOX, "pad": 0.2},
                )
    return beyond


def _statement(ax, ds, text, lhs, rhs):
    """The paper's comparison of two scalars of the dataset, with the run's two values beside it."""
    if lhs not in ds or rhs not in ds:
        return
    a, b = float(ds[lhs]), float(ds[rhs])
    units = ds[lhs].attrs.get("units", "")

    def value(name, v):  # a metric the step-halving check withheld is NaN in the dataset: say so
        return f"{name.replace('_', ' ')} " + (f"{v:.3g} {units}" if np.isfinite(v) else "withheld")

    if np.isfinite(a) and np.isfinite(b):
        verdict = "so it holds here" if a > b else "not here"
    else:
        verdict = "not decided (not converged at half step)"
    here = f"here: {value(lhs, a)} vs {value(rhs, b)}"
    box = dict(fc="white", ec=PAPER_COLOUR, alpha=0.85, pad=0.3, lw=0.6)
    axes_note(ax, 0.01, 0.97, f"{text}\n{here}\n{verdict}", ha="left", va="top", color=PAPER_COLOUR, bbox=box)


def _first_mode_growth(ax, ds, legend: bool):
    """The first contact-held mode's amplitude at node 1 (demodulated per window, relative to the first
    window; both step sizes where the step changes it) against the linearised sliding system's growth
    e^(lambda t): what decides "the oscillation grows"."""
    if "first_mode_amplitude" not in ds or ds["mode_window_time"].size < 2:
        ax.text(0.5, 0.5, "first-mode amplitude not recorded", transform=ax.transAxes, ha="center")
        return
    t = ds["mode_window_time"].values
    full = ds.get("first_mode_amplitude_full_step", ds["first_mode_amplitude"]).values
    rel = full / (full[0] if full[0] > 0 else 1.0)
    lo, hi = float(np.nanmin(rel)), float(np.nanmax(rel))
    # log axes only where the amplitude spans decades (the held Section 10 mode decays 1e-7 in 1 s)
    log = hi / max(lo, 1e-300) > 10
    if log:
        ax.set_yscale("log")
    f1 = float(ds["first_mode_frequency"]) if "first_mode_frequency" in ds else float("nan")
    ax.plot(t, rel, "o-", ms=2.5, lw=1.0, color="C0", label=f"first mode ({f1:.4g} Hz), node 1, dt")
    half = ds.get("first_mode_amplitude_half_step")
    if half is not None:
        ax.plot(t, half.values / full[0], "x--", ms=3, lw=0.8, color="0.45", label="at dt/2")
    lin = float(ds["first_mode_growth_rate_linear"]) if "first_mode_growth_rate_linear" in ds else np.nan
    if np.isfinite(lin):
        line = np.exp(np.minimum(lin * (t - t[0]), 700.0))
        ax.plot(t, line, ":", color="k", lw=1.2, label=f"linear estimate {lin:+.3g} 1/s (eigen-analysis)")
    # the data's range: a fast linear growth (Section 10's axial mode, +900 1/s) leaves the axes
    span = max(hi - lo, 0.04)  # a flat amplitude stays flat on the axes, not magnified noise
    ax.set_ylim(*((lo / 1.5, hi * 1.5) if log else (lo - 0.15 * span, hi + 0.15 * span)))
    if not log:
        ax.ticklabel_format(axis="y", useOffset=False)
    rate = ds.get("first_mode_growth_rate_full_step", ds.get("first_mode_growth_rate"))
    if rate is not None and np.isfinite(float(rate)):
        note = str(ds["first_mode_growth_rate"].attrs.get("step_halving", ""))
        note = "not converged at dt/2" if note.startswith("not converged") else note
        text = f"fitted over the leading segment: {float(rate):+.3g} 1/s" + (f" ({note})" if note else "")
        axes_note(ax, 0.99, 0.04, text, ha="right", fontsize=7.5, bbox=NOTE_BOX)
    ax.set_ylabel("first-mode\namplitude / first", fontsize=8)
    ax.grid(alpha=0.25, which="both")
    ax.tick_params(labelsize=8)
    if legend:
        _legend_above(ax, ncol=3)


# ------------------------------------------------------------------------------------ along-the-beam figures
def _params(ds) -> dict:
    return json.loads(ds.attrs["parameters"])


def paper_mode_shape_figure(ds, scene: str = "", reading: str = "lower_face_drop", n_modes: int = 4):
    """Paper Fig. 22 ("mode shape at system frequency"): the static deflection and the first ``n_modes``
    contact-held modes along the beam, each labelled with its frequency, and the first mode that moves node
    1 mostly horizontally (the axial mode whose stick-slip rides on the bending motion)."""
    x = ds.node_position.values
    f = ds.natural_frequency.values
    v, h = ds.mode_shape_vertical.values, ds.mode_shape_horizontal.values
    fig, (a0, a1) = plt.subplots(2, 1, figsize=(10, 7), sharex=True, height_ratios=[1, 2])
    a0.plot(
        x, ds.static_deflection_vertical.values, "o-", ms=3, color="k", label="static deflection (in contact)"
    )
    a0.axhline(0, color="0.6", lw=0.6)
    a0.set_ylabel("vertical deflection [mm]")
    sci_ticks(a0)
    a0.legend(fontsize=8, loc="lower left")
    a0.grid(alpha=0.25)
    bending = [k for k in range(f.size) if np.abs(v[k]).max() >= np.abs(h[k]).max()][:n_modes]
    for k in bending:
        a1.plot(x, v[k], "o-", ms=3, lw=1.2, label=f"mode {k + 1}: {f[k]:.0f} Hz (vertical component)")
    axial = [k for k in range(f.size) if np.abs(h[k]).max() > np.abs(v[k]).max()]
    if axial:
        k = axial[0]
        a1.plot(
            x,
            h[k],
            "--",
            color="0.35",
            lw=1.2,
            label=f"mode {k + 1}: {f[k]:.0f} Hz, first axial (horizontal component)",
        )
    a1.axhline(0, color="0.6", lw=0.6)
    a1.set_ylabel("mode shape (largest = 1)")
    a1.set_xlabel("position along the beam x [mm] (clamp at 0, node 1 on the disc at the free end)")
    a1.legend(fontsize=8, loc="lower left", ncol=1)
    a1.grid(alpha=0.25)
    rev = _disc_speed(ds)[0]
    note = f" (the disc turns at {rev / 60:.3g} rev/s, far below every mode)" if rev else ""
    a1.set_title(f"contact-held modes (node 1 pinned on the disc){note}", fontsize=9)
    fig.suptitle(
        _title(22, "Beam on disc mode shape, at system frequency 15.2 rev/min", [scene], reading), fontsize=11
    )
    fig.subplots_adjust(left=0.09, right=0.98, top=0.9, bottom=0.08, hspace=0.25)
    return fig


def _absolute(ds, node_value_min, node_value_max, static_at_node):
    """Range of a binned displacement series as an absolute deflection: a drop start is undeformed, so the
    series already is the deflection; a static start measures from the static shape, which is added."""
    start = initial_state_of(_params(ds)["solver"].get("initial_state"))
    offset = 0.0 if start == "drop" else static_at_node
    return node_value_min + offset, node_value_max + offset, start


def paper_deflection_figure(
    datasets: dict, reading: str = "lower_face_drop", several_times: float | None = None
):
    """Paper Fig. 31 (beam deflection with penalty contact): the static deflection along the beam of each
    scene and, as bars at node 1 (x = L) and at mid-span (x = L/2), the range of the vertical displacement
    over the run; below, the normal force over the run relative to the static one, with the zero line and
    the paper's "several times" (``several_times``)."""
    fig, (a0, a1) = plt.subplots(2, 1, figsize=(11, 8), height_ratios=[3, 2])
    names = list(datasets)
    for j, (scene, ds) in enumerate(datasets.items()):
        c = f"C{j}"
        x = ds.node_position.values
        length = float(_params(ds)["beam"]["length"])
        static = ds.static_deflection_vertical.values
        a0.plot(x, static, "-", color=c, lw=1.4, alpha=0.8, label=f"{scene}: static deflection")
        dx = (j - (len(names) - 1) / 2) * 0.012 * length
        for var, xn in (("vertical_displacement", length), ("midspan_vertical_displacement", length / 2)):
            lo, hi = float(np.nanmin(ds[f"{var}_min"])), float(np.nanmax(ds[f"{var}_max"]))
            lo, hi, start = _absolute(ds, lo, hi, float(np.interp(xn, x, static)))
            a0.plot(
                [xn + dx] * 2,
                [lo, hi],
                color=c,
                lw=5,
                alpha=0.6,
                solid_capstyle="butt",
                label=f"{scene}: range over the run (start: {start})" if xn == length else None,
            )
            a0.plot([xn + dx] * 2, [lo, hi], "_", color=c, ms=12)
        tc, lo, hi = band_columns(ds, "normal_force")
        n0 = float(ds["static_normal_force"])
        a1.fill_between(tc, lo / n0, hi / n0, color=c, alpha=0.4, lw=0, label=f"{scene}: min-max")
    a0.axhline(0, color="0.6", lw=0.6)
    for xn, text in ((length, "node 1 (x = L)"), (length / 2, "mid-span (x = L/2)")):
        a0.annotate(text, (xn, 0), xytext=(0, 8), textcoords="offset points", ha="center", fontsize=8)
    a0.set_xlabel("position along the beam x [mm] (clamp at 0)")
    a0.set_ylabel("vertical deflection [mm]")
    sci_ticks(a0)
    a0.grid(alpha=0.25)
    a0.legend(fontsize=8, loc="lower left")
    a1.axhline(0, color=PAPER_COLOUR, lw=1.0, label="zero: separation below")
    a1.axhline(1, color="0.3", ls=":", lw=1, label="static N")
    if several_times:
        text = f"paper: 'several times' the initial N (read as {several_times:g} N0)"
        paper_line(a1, several_times, text, bbox=None)
    a1.set_xlabel("time [s] (whole run)")
    a1.set_ylabel("normal force / static N")
    a1.grid(alpha=0.25)
    a1.legend(fontsize=8, loc="upper right", ncol=2)
    a1.set_xlim(0, max(float(ds.bin_time.values[-1]) for ds in datasets.values()))
    fig.suptitle(
        _title(31, "Beam on rotating disc deflection with penalty contact", names, reading), fontsize=11
    )
    fig.subplots_adjust(left=0.08, right=0.98, top=0.9, bottom=0.07, hspace=0.3)
    return fig


# -------------------------------------------------------------------------------------- boundary sketches
def paper_boundary_sketch(ds, number: int, scene: str = ""):
    """Paper Figs. 26 / 34 (boundary conditions), drawn to scale from the scene's ``parameters``: clamped
    left end, the beam, the disc under the free end at the contact angle, node 1, and (method fixed_normal)
    the upper face held vertically."""
    p = _params(ds)
    L, h = float(p["beam"]["length"]), float(p["beam"]["thickness"])
    R = float(p["disc"]["diameter"]) / 2
    con = p["contact"]
    a = np.radians(float(con.get("angle_deg", 0.0)))
    n = np.array([-np.sin(a), np.cos(a)])  # outward disc normal at the contact (as stickslip.fe.contact)
    corner = np.array([L, -h / 2])
    centre = corner - R * n
    fig, ax = plt.subplots(figsize=(11, 3.6))
    ax.add_patch(Rectangle((-6, -10), 6, 20, fill=False, hatch="////", lw=0, ec="0.3"))
    ax.plot([0, 0], [-10, 10], color="k", lw=1.5)
    ax.add_patch(Rectangle((0, -h / 2), L, h, fc="0.55", ec="k", lw=0.8))
    ax.add_patch(Circle(centre, R, fc="#dbe8f5", ec="C0", lw=1.2))
    ax.plot(*centre, "+", color="C0")
    ax.add_patch(
        FancyArrowPatch(
            centre + R * 0.55 * np.array([-0.7, 0.7]),
            centre + R * 0.55 * np.array([0.7, 0.7]),
            connectionstyle="arc3,rad=-0.4",
            arrowstyle="-|>",
            mutation_scale=12,
            color="C0",
        )
    )
    ax.text(
        *(centre + [0, -0.35 * R]), "rigid disc\nclockwise", ha="center", va="center", fontsize=8, color="C0"
    )
    ax.plot(*corner, "o", color=PAPER_COLOUR, ms=5, zorder=5)
    ax.annotate(
        "node 1 (contact, lower face)",
        corner,
        xytext=(-150, -28),
        textcoords="offset points",
        fontsize=8,
        color=PAPER_COLOUR,
        arrowprops=dict(arrowstyle="->", color=PAPER_COLOUR),
    )
    ax.annotate("", corner + 6 * n, corner, arrowprops=dict(arrowstyle="-|>", color="k"))
    ax.text(*(corner + 6.5 * n + [0.8, 0]), "contact normal", fontsize=8)
    if a != 0:
        ax.plot([centre[0], centre[0]], [centre[1], centre[1] + 1.25 * R], color="0.4", lw=0.8, ls=":")
        ax.plot([centre[0], corner[0]], [centre[1], corner[1]], color="0.4", lw=0.8, ls=":")
        ax.add_patch(Arc(centre, 1.2 * R, 1.2 * R, theta1=90, theta2=90 + np.degrees(a), color="k", lw=1))
        mid = centre + 0.7 * R * np.array([-np.sin(a / 2), np.cos(a / 2)])
        ax.text(*mid, f"{np.degrees(a):g}°", fontsize=9, ha="right", va="bottom")
    ax.annotate(
        "", (L / 2, -h / 2 - 6), (L / 2, -h / 2 - 0.5), arrowprops=dict(arrowstyle="-|>", color="0.3")
    )
    ax.text(L / 2 + 1, -h / 2 - 4, "g: own weight only", fontsize=8, color="0.3")
    if con.get("method") == "fixed_normal":
        xs = np.linspace(5, L - 5, 10)
        for xr in xs:
            ax.add_patch(Circle((xr, h / 2 + 0.6), 0.6, fc="white", ec="k", lw=0.8))
        ax.plot([0, L], [h / 2 + 1.2] * 2, color="k", lw=1)
        ax.add_patch(Rectangle((0, h / 2 + 1.2), L, 1.5, fill=False, hatch="////", lw=0, ec="0.3"))
        held = "upper face held vertically (rollers: free horizontally, no vertical motion)"
        ax.text(L / 2, h / 2 + 3.2, held, ha="center", fontsize=8)
    ax.annotate("", (0, h / 2 + 7), (L, h / 2 + 7), arrowprops=dict(arrowstyle="<->", color="0.3", lw=0.8))
    ax.text(L / 2, h / 2 + 7.5, f"L = {L:g} mm, h = {h:g} mm (beam)", ha="center", fontsize=8)
    ax.text(-5, 11, "clamped", fontsize=8)
    speed, surf = _disc_speed(ds)
    speed_txt = f"{surf:.3g} mm/s at the surface"
    speed_txt = f"{speed:g} rev/min\n({speed_txt})" if speed else speed_txt
    disc = f"D = {2 * R:g} mm\n{speed_txt}\n{METHOD_NOTE.get(con.get('method'), con.get('method'))}"
    ax.text(centre[0] + R + 2, centre[1], disc, fontsize=8, va="center")
    ax.set_aspect("equal")
    ax.set_xlim(-10, centre[0] + R + 38)
    ax.set_ylim(centre[1] - R - 2, h / 2 + 14)
    ax.set_xlabel("x [mm] (to scale)")
    ax.set_ylabel("y [mm]")
    captions = {
        26: "Beam on disc boundary condition with rotating velocity 0.5 mm/sec",
        34: "Beam on rotating disc with kinematic contact method, the angle of the contact is 30 degrees",
    }
    fig.suptitle(f"Fig. {number}: {captions.get(number, 'boundary condition')} — {scene}", fontsize=11)
    fig.subplots_adjust(left=0.07, right=0.98, top=0.9, bottom=0.12)
    return fig


def paper_figure(number: int, datasets: dict, reported=(), reading: str = "lower_face_drop", **kw):
    """Any of the paper's Figs. 21-36 from its section's scene datasets (name -> dataset)."""
    if number in TIME_SERIES:
        return paper_time_series_figure(number, datasets, reported, reading)
    scene, ds = next(iter(datasets.items()))
    if number == 22:
        return paper_mode_shape_figure(ds, scene, reading)
    if number == 31:
        return paper_deflection_figure(datasets, reading, several_times=kw.get("several_times"))
    if number == 26:  # the paper's caption names 0.5 mm/s
        scene = next((s for s in datasets if s.endswith("0p5mm_s")), scene)
        return paper_boundary_sketch(datasets[scene], number, scene)
    if number == 34:
        return paper_boundary_sketch(ds, number, scene)
    raise ValueError(f"paper figure {number}: not a beam-on-disc figure (21-36)")
