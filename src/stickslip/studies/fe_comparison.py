"""Beam (frame elements with rotary inertia) against the continuum strip (the paper's kind of model): the
comparison table's rows (agreement within the beam's own step-halving noise, notes), over the comparison
window and over the claims' windows, and its datasets. The continuum's runs: stickslip.studies.fe_continuum.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.quantities import INTERPRETATION, RESPONSE_QUANTITIES, cf_attrs
from ..fe.step_halving import REL_TOL, converged, sign_converged

#: quantities of the comparison table
QUANTITIES = RESPONSE_QUANTITIES
#: largest |relative difference| that counts as agreement
AGREEMENT_REL = 0.05
#: the rule of the agreement column, printed beside it in every table row
AGREEMENT_RULE = (
    f"|beam - continuum| / |continuum| <= {AGREEMENT_REL:g}, or |continuum| and |beam| both <= noise_floor "
    "(the beam's own change of the quantity when its time step is halved); dominant_frequency also needs "
    "horizontal_amplitude to agree (a frequency of two motions of different size is not one result)"
)


def step_pair(ds: xr.Dataset, name: str) -> tuple[float, float]:
    """(value at dt, value at dt/2) of a step-halved metric: ``<name>_full_step`` where the check removed
    it, else ``<name>``; ``<name>_half_step`` (NaN when the dataset has none)."""
    full = ds[f"{name}_full_step"] if f"{name}_full_step" in ds else ds.get(name)
    half = ds.get(f"{name}_half_step")
    return (
        float(full) if full is not None else float("nan"),
        float(half) if half is not None else float("nan"),
    )


#: quantities compared over a claim's window (beam dataset of the default reading vs continuum window run):
#: every scalar both datasets hold at dt and at dt/2 (window_quantities), these first
WINDOW_QUANTITIES = ("first_mode_growth_rate", "separation_burst_time")


def window_quantities(continuum: xr.Dataset, beam: xr.Dataset) -> list[str]:
    """Every scalar quantity both models' window datasets hold at dt and dt/2 (WINDOW_QUANTITIES first):
    whatever a claim reads from the beam over that window is compared, not a chosen few."""

    def scalars(ds):
        return {
            str(n) for n, v in ds.data_vars.items()
            if v.ndim == 0 and v.dtype.kind in "fiu" and f"{n}_half_step" in ds.data_vars
        }  # fmt: skip

    shared = scalars(continuum) & scalars(beam)
    return [q for q in WINDOW_QUANTITIES if q in shared] + sorted(shared - set(WINDOW_QUANTITIES))


#: the rule of the window rows' agreement column
WINDOW_RULE = (
    "none of the four values (beam and continuum, each at dt and dt/2) finite: both models say it does not "
    "happen (no separation, no growth segment); else the beam's value converged under step halving (its "
    "dt/dt/2 change within the step-halving rule; a growth rate: its sign), all four finite and of one sign, "
    "and the two models' [min, max] ranges over dt and dt/2 overlap (the models differ by no more than the "
    f"step moves either) or their dt/dt/2 means differ by <= {REL_TOL:g} relatively. A beam value that moves "
    "under step halving agrees with nothing: a wide dt/dt/2 range would overlap almost any continuum value"
)


def beam_converged(beam: tuple[float, float], quantity: str = "", unit: str = "1") -> bool:
    """Does the beam's (dt, dt/2) pair pass the step-halving rule (a SIGN_ONLY quantity: or its sign)?"""
    return bool(np.all(converged(*beam, unit))) or sign_converged(quantity, *beam)


def window_agrees(
    beam: tuple[float, float],
    continuum: tuple[float, float],
    rel: float = REL_TOL,
    quantity: str = "",
    unit: str = "1",
) -> bool:
    """WINDOW_RULE for (dt, dt/2) pairs of one quantity (of ``unit``) in the two models."""
    v = np.array([*beam, *continuum], dtype=float)
    if np.all(np.isnan(v)) or np.all(v == v[0]):  # both say it does not happen, or all four are one value
        return True
    if not np.all(np.isfinite(v)) or np.any(v == 0) or len(set(np.sign(v))) != 1:
        return False
    if not beam_converged(beam, quantity, unit):
        return False
    b, c = v[:2], v[2:]
    overlap = b.min() <= c.max() and c.min() <= b.max()
    return bool(overlap or abs(b.mean() - c.mean()) <= rel * abs(c.mean()))


def window_rows(
    continuum: Mapping[str, xr.Dataset],
    beam: Mapping[str, xr.Dataset],
    notes: Mapping[str, str] | None = None,
) -> list[dict]:
    """One row per (scene, window_quantities) over the claim's window: both models' values at dt and dt/2,
    the agreement under WINDOW_RULE and, where they disagree, the config's note or one stating the numbers."""
    notes = notes or {}
    rows = []
    for scene, cds in continuum.items():
        for q in window_quantities(cds, beam[scene]):
            c, b = step_pair(cds, q), step_pair(beam[scene], q)
            unit = str(beam[scene][q].attrs.get("units", "1")) if q in beam[scene] else "1"
            ok = window_agrees(b, c, quantity=q, unit=unit)
            note = "" if ok else _window_note(notes, scene, q, b, c, unit)
            floor = max(abs(c[1] - c[0]), abs(b[1] - b[0]))
            rows.append(_row(scene, q, c, b, floor, ok, note, "claim", cds, WINDOW_RULE))
    return rows


def _row(scene, quantity, continuum, beam, noise_floor, ok, note, window, ds, rule) -> dict:
    """A row of the comparison table: ``continuum`` and ``beam`` are (dt, dt/2) values."""
    return {
        "scene": scene,
        "quantity": quantity,
        "continuum": continuum[0],
        "beam": beam[0],
        "relative_difference": relative_difference(continuum[0], beam[0]),
        "noise_floor": noise_floor,
        "agreement": ok,
        "agreement_rule": rule,
        "note": note,
        "window": window,
        "t_end": float(ds.attrs.get("t_end", np.nan)),
        "continuum_half_step": continuum[1],
        "beam_half_step": beam[1],
    }


def noise_floors(metrics: Mapping, metrics_half_step: Mapping) -> dict:
    """Per quantity: |m(dt/2) - m(dt)|, the change of the beam's own number when its step is halved."""
    return {q: abs(float(metrics_half_step[q]) - float(metrics[q])) for q in QUANTITIES}


def relative_difference(continuum: float, beam: float) -> float:
    """(beam - continuum) / |continuum| (0 when both are 0, inf when only the continuum is 0)."""
    if continuum == 0:
        return 0.0 if beam == 0 else float("inf")
    return (beam - continuum) / abs(continuum)


def agrees(continuum: float, beam: float, noise_floor: float = 0.0, rel: float = AGREEMENT_REL) -> bool:
    """AGREEMENT_RULE: within ``rel`` relatively (fractions too), or both values inside the measured noise
    floor (then neither number is a result, and they cannot disagree)."""
    if max(abs(continuum), abs(beam)) <= noise_floor:
        return True
    return bool(abs(relative_difference(continuum, beam)) <= rel)


def _configured_note(notes: Mapping[str, str], scene: str, q: str) -> str:
    """The config's note for (scene, quantity) (keys scene.quantity, scene, quantity), else ""."""
    return " ".join(str(notes[k]) for k in (f"{scene}.{q}", scene, q) if k in notes)


def _note(notes: Mapping[str, str], scene: str, q: str, continuum: float, beam: float) -> str:
    """The config's note for a disagreeing (scene, quantity), else one that states the numbers: no
    disagreeing row goes without a note."""
    return _configured_note(notes, scene, q) or (
        f"beam {beam:.4g} vs continuum {continuum:.4g} do not agree (no explanation in fe.comparison.notes)"
    )


def _window_note(notes: Mapping[str, str], scene: str, q: str, beam, continuum, unit: str) -> str:
    """The config's note for a disagreeing window row, else why: the beam's value moves under step
    halving, or the two models' numbers."""
    if not _configured_note(notes, scene, q) and not beam_converged(beam, q, unit):
        return (
            f"the beam's value moves under step halving ({beam[0]:.4g} at dt, {beam[1]:.4g} at dt/2): no "
            "comparison can back it"
        )
    return _note(notes, scene, q, continuum[0], beam[0])


def comparison_rows(
    continuum: Mapping[str, xr.Dataset],
    beam: Mapping[str, Mapping],
    notes: Mapping[str, str] | None = None,
    floors: Mapping[str, Mapping] | None = None,
    beam_half_step: Mapping[str, Mapping] | None = None,
) -> list[dict]:
    """One row per (scene, quantity): continuum, beam, relative difference, the noise floor (``floors``
    [scene][quantity], 0 when not measured), the agreement flag and its rule, and for a row that does not
    agree the config's note for the scene (or the quantity), or one stating the numbers (_note). Columns
    shared with window_rows: ``window`` ("short"), ``t_end``, the beam's value at half the step
    (``beam_half_step``[scene][quantity], NaN when not given) and the continuum's (not run: NaN)."""
    notes = notes or {}
    floors = floors or {}
    beam_half_step = beam_half_step or {}
    rows = []
    for scene, ds in continuum.items():
        ok_of = {}
        for q in QUANTITIES:
            c, b = float(ds[q]), float(beam[scene][q])
            floor = float(floors.get(scene, {}).get(q, 0.0))
            ok = ok_of[q] = agrees(c, b, floor)
            if q == "dominant_frequency":
                ok = ok and ok_of.get("horizontal_amplitude", True)
            note = "" if ok else _note(notes, scene, q, c, b)
            pair = (b, float(beam_half_step.get(scene, {}).get(q, np.nan)))
            rows.append(_row(scene, q, (c, float("nan")), pair, floor, ok, note, "short", ds, AGREEMENT_RULE))
    return rows


def comparison_dataset(rows: list[dict], continuum: Mapping[str, xr.Dataset], beam: Mapping[str, Mapping]):
    """The comparison table as a dataset (scene x quantity), with the CPU times of both models; the rows over
    a claim's window (window_rows) as ``window_*`` variables (window_dataset)."""
    scenes = list(continuum)
    qs = list(QUANTITIES)
    keys = ("continuum", "beam", "relative_difference", "noise_floor", "agreement")
    arr = {k: np.full((len(scenes), len(qs)), np.nan) for k in keys}
    for r in (r for r in rows if r.get("window", "short") == "short"):
        i, j = scenes.index(r["scene"]), qs.index(r["quantity"])
        for k in arr:
            arr[k][i, j] = float(r[k])
    dims = ("scene", "quantity")
    rel = arr["relative_difference"]
    ds = xr.Dataset(
        {
            "continuum_value": cf_variable(dims, arr["continuum"], "1", "continuum strip value"),
            "beam_value": cf_variable(dims, arr["beam"], "1", "beam model value"),
            "relative_difference": cf_variable(dims, rel, "1", "(beam - continuum) / |continuum|"),
            "noise_floor": cf_variable(
                dims,
                arr["noise_floor"],
                "1",
                "beam's change of the quantity at half the time step (quantity's units)",
            ),
            "agreement": cf_variable(
                dims, arr["agreement"].astype("i1"), "1", "beam and continuum agree", rule=AGREEMENT_RULE
            ),
            **{
                f"{model}_cpu_time": cf_variable(
                    "scene",
                    np.array([float(runs[s]["cpu_time"]) for s in scenes]),
                    "s",
                    f"CPU time of the {model} run",
                )
                for model, runs in (("continuum", continuum), ("beam", beam))
            },
        },
        coords={"scene": ("scene", scenes), "quantity": ("quantity", qs)},
    )
    ds["max_abs_relative_difference"] = cf_variable(
        "quantity",
        np.nanmax(np.abs(np.where(np.isfinite(rel), rel, np.nan)), 0),
        "1",
        "largest |relative difference| over the scenes",
    )
    ds.attrs.update(
        cf_attrs(
            "Beam vs continuum strip on the paper scenes",
            model_interpretation=INTERPRETATION,
            method="both models from the same scene mapping and window",
        )
    )
    window = [r for r in rows if r.get("window") == "claim"]
    return ds.merge(window_dataset(window)) if window else ds


def window_dataset(rows: list[dict]) -> xr.Dataset:
    """The rows over a claim's window (window_rows) as ``window_scene x window_quantity (x time_step)``."""
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    qs = list(dict.fromkeys(r["quantity"] for r in rows))
    shape = (len(scenes), len(qs))
    beam, cont = np.full((*shape, 2), np.nan), np.full((*shape, 2), np.nan)
    ok, t_end = np.zeros(shape, "i1"), np.full(len(scenes), np.nan)
    for r in rows:
        i, j = scenes.index(r["scene"]), qs.index(r["quantity"])
        beam[i, j] = r["beam"], r["beam_half_step"]
        cont[i, j] = r["continuum"], r["continuum_half_step"]
        ok[i, j] = bool(r["agreement"])
        t_end[i] = r["t_end"]
    dims = ("window_scene", "window_quantity", "time_step")
    return xr.Dataset(
        {
            "window_beam_value": cf_variable(dims, beam, "1", "beam model value (quantity's units)"),
            "window_continuum_value": cf_variable(
                dims, cont, "1", "continuum strip value (quantity's units)"
            ),
            "window_agreement": cf_variable(dims[:2], ok, "1", "beam and continuum agree", rule=WINDOW_RULE),
            "window_t_end": cf_variable("window_scene", t_end, "s", "claim window of both runs"),
        },
        coords={
            "window_scene": ("window_scene", scenes),
            "window_quantity": ("window_quantity", qs),
            "time_step": ("time_step", ["dt", "dt/2"], {"long_name": "explicit time step"}),
        },
    )
