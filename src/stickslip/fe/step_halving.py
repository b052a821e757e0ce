"""Step-halving check of explicit runs: a metric that moves beyond its tolerance when the time step is
halved is not a result of the model but of the step, and no claim may read it.

A run is repeated at half its time step (safety factor x 0.5). For each checked metric the change
|m(dt/2) - m(dt)| is compared with ``REL_TOL`` of the larger magnitude, or with an absolute floor per
unit far below every number the paper reports (``ABS_FLOOR``). A metric that fails is replaced by NaN in
the dataset (the claims table then calls its claim not comparable), its full-step value is kept as
``<name>_full_step`` and the reason is written to the variable's ``step_halving`` attribute. Along a sweep
the check is per member: only the members that fail are removed, so a trend is fitted over converged
members only.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # the workflow reads HALF_STEP at parse time, where xarray would cost every no-op 0.5 s
    import xarray as xr

#: the step-halving factor of the time step (on the explicit safety factor)
HALF_STEP = 0.5
#: largest relative change under step halving that still counts as converged
REL_TOL = 0.05
#: absolute change per unit that always counts as converged (1e-4 of the smallest FE number the paper
#: gives, 1.5e-4 mm; a thousandth of the increments for fractions)
ABS_FLOOR = {"mm": 1e-8, "mm s-1": 1e-6, "1": 1e-3, "Hz": 1e-3, "N": 1e-9, "s": 1e-6, "s-1": 1e-6}
#: metrics that describe the run, not the motion (the step itself, its cost)
NOT_CHECKED = (
    "cpu_time",
    "time_step",
    "stable_time_step",
    "increment_count",
    "increment_count_0p65s",
    "disc_surface_speed",
    "horizontal_velocity_trend",
    "vertical_velocity_trend",
    "horizontal_displacement_trend",
)
#: metrics whose claims read only their sign (a growth rate: does the mode grow or decay): converged when
#: both steps give the same non-zero sign; a value that moves beyond REL_TOL keeps that change in its
#: ``step_halving`` attribute (the claims table's ensemble, which holds the half-step run, decides whether
#: the sign is beyond the noise)
SIGN_ONLY = ("first_mode_growth_rate",)
RULE = (
    f"converged when |m(dt/2) - m(dt)| <= {REL_TOL:g} max(|m(dt)|, |m(dt/2)|) or <= the unit's floor "
    + ", ".join(f"{v:g} {k}" for k, v in ABS_FLOOR.items())
)


def same_sign(full, half) -> np.ndarray:
    """Element-wise: both finite, non-zero and of one sign."""
    a = np.asarray(full, dtype=float)
    b = np.asarray(half, dtype=float)
    with np.errstate(invalid="ignore"):
        return np.isfinite(a) & np.isfinite(b) & (np.sign(a) == np.sign(b)) & (a != 0)


def converged(full, half, unit: str) -> np.ndarray:
    """Element-wise: does the metric (scalar or array) pass the step-halving rule?"""
    a = np.asarray(full, dtype=float)
    b = np.asarray(half, dtype=float)
    change = np.abs(b - a)
    with np.errstate(invalid="ignore"):
        ok = (change <= REL_TOL * np.maximum(np.abs(a), np.abs(b))) | (change <= ABS_FLOOR.get(unit, 0.0))
    both_nan = np.isnan(a) & np.isnan(b)
    return ok | both_nan


def sign_converged(name: str, full, half) -> bool:
    """A SIGN_ONLY metric whose every value keeps its non-zero sign at half the step: converged for the
    claims that read it, however far its value moves."""
    return name in SIGN_ONLY and bool(np.all(same_sign(full, half)))


def apply_step_halving(ds: xr.Dataset, half: Mapping[str, object], along: str | None = None) -> xr.Dataset:
    """Copy of ``ds`` with every metric of ``half`` (its values at half the time step) checked.

    Scalars and per-window envelopes (``window`` dimension: one failing window removes the whole
    envelope, a trend over the rest would be biased) become NaN when they fail; along a sweep dimension
    ``along`` only the failing members do. Ensemble companions (``<name>_ensemble``) are masked alike."""
    new: dict = {}  # collected and assigned at once: assigning one by one re-aligns the dataset each time
    report = []
    for name, h in half.items():
        if name in NOT_CHECKED or name not in ds:
            continue
        var = ds[name]
        unit = str(var.attrs.get("units", "1"))
        hv = np.asarray(h, dtype=float).reshape(var.shape)
        ok = converged(var.values, hv, unit)
        sign_only = not np.all(ok) and sign_converged(name, var.values, hv)
        if sign_only:
            change = float(np.max(np.abs(hv - var.values) / np.abs(var.values)))
            note = f"sign converged, value moves {100 * change:.1f} % at half step"
            new[name] = (var.dims, var.values, {**var.attrs, "step_halving": note})
            ok = np.ones_like(ok)
        if along is not None and along in var.dims:
            bad = ~ok
        else:
            bad = np.broadcast_to(~np.all(ok), var.shape)
        long_name = var.attrs.get("long_name", name)
        new[f"{name}_half_step"] = (
            var.dims,
            hv,
            {"units": unit, "long_name": f"{long_name}, at half the time step"},
        )
        if not np.any(bad):
            continue
        full = var.values.astype(float)
        new[f"{name}_full_step"] = (
            var.dims,
            full,
            {"units": unit, "long_name": f"{long_name}, not converged (full step)"},
        )
        new[name] = (
            var.dims,
            np.where(bad, np.nan, full),
            {**var.attrs, "step_halving": "not converged: " + RULE},
        )
        ens = ds.get(f"{name}_ensemble")
        if ens is not None:
            new[f"{name}_ensemble"] = (ens.dims, np.where(bad, np.nan, ens.values.astype(float)), ens.attrs)
        report.append(name)
    out = ds.assign(new)
    out.attrs["step_halving_rule"] = RULE
    out.attrs["step_halving_not_converged"] = ", ".join(report) if report else "none"
    return out
