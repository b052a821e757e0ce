"""Beam (frame elements with rotary inertia) against the continuum strip (the paper's kind of model).

Both models are built from the same merged scene mapping. The beam's Section 10 scene (``fixed_normal``:
transverse motion suppressed, normal force held) is run in the continuum as the paper describes it:
kinematic contact with the upper face held vertically (``constrain_upper_face``).
"""

from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..catalogue import fe_continuum_window
from ..ensemble import EnsembleSpec, ensemble_dataset, step_member_values
from ..fe.metrics import trajectory_metrics
from ..fe.params import FrictionTable
from ..fe.scene import SceneParams
from ..fe.step_halving import HALF_STEP, REL_TOL, apply_step_halving
from .fe import INTERPRETATION, mode_growth, result_dataset, run_scene

#: quantities of the comparison table
QUANTITIES = (
    "horizontal_amplitude",
    "mean_horizontal_displacement",
    "dominant_frequency",
    "stick_fraction",
    "separation_fraction",
)
#: largest |relative difference| that counts as agreement
AGREEMENT_REL = 0.05
#: the rule of the agreement column, printed beside it in every table row
AGREEMENT_RULE = (
    f"|beam - continuum| / |continuum| <= {AGREEMENT_REL:g}, or |continuum| and |beam| both <= noise_floor "
    "(the beam's own change of the quantity when its time step is halved); dominant_frequency also needs "
    "horizontal_amplitude to agree (a frequency of two motions of different size is not one result)"
)


def _params(mapping: Mapping) -> SceneParams:
    return SceneParams.from_mapping(
        {k: v for k, v in mapping.items() if k in ("beam", "disc", "contact", "solver")}
    )


def continuum_scene_from_mapping(mapping: Mapping, friction: FrictionTable, nx: int, ny: int):
    """The continuum scene of a beam scene mapping (same geometry reading, damping and contact law)."""
    from dataclasses import replace

    from ..fe.continuum import build_continuum

    p = _params(mapping)
    contact = p.contact
    upper = contact.method == "fixed_normal"
    if upper:
        contact = replace(contact, method="kinematic")
    return build_continuum(
        p.beam,
        p.disc,
        contact,
        friction,
        nx=nx,
        ny=ny,
        output_node=p.contact.output_node,
        damping_beta=p.solver.stiffness_damping,
        disc_rotation=p.disc.direction,
        constrain_upper_face=upper,
        contact_position=None if p.contact.surface_offset else None,
    )


def continuum_dataset(
    mapping: Mapping, friction: FrictionTable, *, nx: int = 100, ny: int = 1, name: str = ""
) -> xr.Dataset:
    """Pure build: run the continuum strip for the scene mapping; the beam dataset's trajectory metrics, and
    the growth of the strip's own first contact-held mode at node 1 (the beam's first_mode_* variables
    but the linear estimate)."""
    from ..fe.continuum import integrate_continuum, natural_frequencies

    p = _params(mapping)
    scene = continuum_scene_from_mapping(mapping, friction, nx, ny)
    r = integrate_continuum(
        scene,
        p.solver.t_end,
        safety_factor=p.solver.safety_factor,
        output_interval=p.solver.output_dt,
        initial_state=p.solver.initial_state,
    )
    m = trajectory_metrics(r)
    growth, r.extra["first_mode_amplitude"] = mode_growth(r, float(natural_frequencies(scene, 1)[0]))
    m.update(growth)
    out = dict(mapping.get("output", {}) or {})
    ds = result_dataset(r, m, windows=out.get("windows"), bin_width=float(out.get("bin_width", 1e-4)))
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": f"Continuum strip {nx}x{ny} on rotating rigid disc, scene {name}".strip(),
            "scene": name,
            "parameters": json.dumps({"mapping": mapping, "nx": nx, "ny": ny}, default=str),
            "model_interpretation": (
                "plane-stress strip, Q4 with incompatible modes (CPS4I kind), lumped mass, node-to-surface "
                "contact of the lower face on the rigid disc; Section 10 as upper face held vertically. "
                "Other choices as the beam model: " + INTERPRETATION
            ),
            "method": f"explicit central difference, dt={r.dt:.6g} s (stable limit {r.dt_crit:.6g} s)",
            "diverged": int(r.extra.get("diverged", False)),
            "t_end": float(p.solver.t_end),
        }
    )
    return ds


def continuum_window_dataset(
    mapping: Mapping, friction: FrictionTable, *, nx: int = 100, ny: int = 1, name: str = ""
) -> xr.Dataset:
    """The continuum strip over a claim's window, as a claims dataset: the base run and its step-halving
    member (dt/2) as the perturbation ensemble (``<metric>_ensemble``, so a claim's spread holds the step's
    effect), every metric checked by stickslip.fe.step_halving (``<metric>_half_step``, NaN and
    ``<metric>_full_step`` where not converged). No perturbed members: at ~16 s CPU per simulated second
    (dt/2: ~26 s) they are not affordable, and the beam's show a 1e-12 perturbation moves its metrics far
    less than the step does."""
    spec = EnsembleSpec(seeds=(), step_factor=HALF_STEP, blas_threads=None)
    ds = ensemble_dataset(  # no perturbed members: the run id and fields decide no sign here
        lambda mp: continuum_dataset(mp, friction, nx=nx, ny=ny, name=name),
        mapping,
        spec,
        run_id=fe_continuum_window(name),
        fields=(),
    )
    ds = apply_step_halving(ds, step_member_values(ds))
    ds.attrs["model"] = "continuum"
    return ds


def step_pair(ds: xr.Dataset, name: str) -> tuple[float, float]:
    """(value at dt, value at dt/2) of a step-halved metric: ``<name>_full_step`` where the check removed
    it, else ``<name>``; ``<name>_half_step`` (NaN when the dataset has none)."""
    full = ds[f"{name}_full_step"] if f"{name}_full_step" in ds else ds.get(name)
    half = ds.get(f"{name}_half_step")
    return (
        float(full) if full is not None else float("nan"),
        float(half) if half is not None else float("nan"),
    )


#: quantities compared over a claim's window (beam dataset of the default reading vs continuum window run)
WINDOW_QUANTITIES = ("first_mode_growth_rate", "separation_burst_time")
#: the rule of the window rows' agreement column
WINDOW_RULE = (
    "none of the four values (beam and continuum, each at dt and dt/2) finite: both models say it does not "
    "happen (no separation, no growth segment); else all four finite and of one sign, and the two models' "
    "[min, max] ranges over dt and dt/2 overlap (the models differ by no more than the step moves either) "
    f"or their dt/dt/2 means differ by <= {REL_TOL:g} relatively"
)


def window_agrees(beam: tuple[float, float], continuum: tuple[float, float], rel: float = REL_TOL) -> bool:
    """WINDOW_RULE for (dt, dt/2) pairs of one quantity in the two models."""
    v = np.array([*beam, *continuum], dtype=float)
    if np.all(np.isnan(v)):
        return True
    if not np.all(np.isfinite(v)) or np.any(v == 0) or len(set(np.sign(v))) != 1:
        return False
    b, c = v[:2], v[2:]
    overlap = b.min() <= c.max() and c.min() <= b.max()
    return bool(overlap or abs(b.mean() - c.mean()) <= rel * abs(c.mean()))


def window_rows(
    continuum: Mapping[str, xr.Dataset],
    beam: Mapping[str, xr.Dataset],
    notes: Mapping[str, str] | None = None,
) -> list[dict]:
    """One row per (scene, WINDOW_QUANTITIES) over the claim's window: both models' values at dt and dt/2,
    the agreement under WINDOW_RULE and, where they disagree, the config's note or one stating the numbers."""
    notes = notes or {}
    rows = []
    for scene, cds in continuum.items():
        for q in WINDOW_QUANTITIES:
            c, b = step_pair(cds, q), step_pair(beam[scene], q)
            ok = window_agrees(b, c)
            rows.append(
                {
                    "scene": scene,
                    "quantity": q,
                    "continuum": c[0],
                    "beam": b[0],
                    "relative_difference": relative_difference(c[0], b[0]),
                    "noise_floor": max(abs(c[1] - c[0]), abs(b[1] - b[0])),
                    "agreement": ok,
                    "agreement_rule": WINDOW_RULE,
                    "note": "" if ok else _note(notes, scene, q, c[0], b[0]),
                    "window": "claim",
                    "t_end": float(cds.attrs.get("t_end", np.nan)),
                    "continuum_half_step": c[1],
                    "beam_half_step": b[1],
                }
            )
    return rows


def beam_metrics(mapping: Mapping, friction: FrictionTable) -> dict:
    _, m, _ = run_scene(mapping, friction)
    return m


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


def _note(notes: Mapping[str, str], scene: str, q: str, continuum: float, beam: float) -> str:
    """The config's note for a disagreeing (scene, quantity) (keys ``scene.quantity``, ``scene``,
    ``quantity``), else one that states the numbers: no disagreeing row goes without a note."""
    text = " ".join(str(notes[k]) for k in (f"{scene}.{q}", scene, q) if k in notes)
    return text or (
        f"beam {beam:.4g} vs continuum {continuum:.4g} do not agree (no explanation in fe.comparison.notes)"
    )


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
            rows.append(
                {
                    "scene": scene,
                    "quantity": q,
                    "continuum": c,
                    "beam": b,
                    "relative_difference": relative_difference(c, b),
                    "noise_floor": floor,
                    "agreement": ok,
                    "agreement_rule": AGREEMENT_RULE,
                    "note": "" if ok else _note(notes, scene, q, c, b),
                    "window": "short",
                    "t_end": float(ds.attrs.get("t_end", np.nan)),
                    "continuum_half_step": float("nan"),
                    "beam_half_step": float(beam_half_step.get(scene, {}).get(q, np.nan)),
                }
            )
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
    ds = xr.Dataset(
        {
            "continuum_value": (dims, arr["continuum"], {"units": "1", "long_name": "continuum strip value"}),
            "beam_value": (dims, arr["beam"], {"units": "1", "long_name": "beam model value"}),
            "relative_difference": (
                dims,
                arr["relative_difference"],
                {"units": "1", "long_name": "(beam - continuum) / |continuum|"},
            ),
            "noise_floor": (
                dims,
                arr["noise_floor"],
                {
                    "units": "1",
                    "long_name": "beam's change of the quantity at half the time step (quantity's units)",
                },
            ),
            "agreement": (
                dims,
                arr["agreement"].astype("i1"),
                {"units": "1", "long_name": "beam and continuum agree", "rule": AGREEMENT_RULE},
            ),
            "continuum_cpu_time": (
                "scene",
                np.array([float(continuum[s]["cpu_time"]) for s in scenes]),
                {"units": "s", "long_name": "CPU time of the continuum run"},
            ),
            "beam_cpu_time": (
                "scene",
                np.array([float(beam[s]["cpu_time"]) for s in scenes]),
                {"units": "s", "long_name": "CPU time of the beam run"},
            ),
        },
        coords={"scene": ("scene", scenes), "quantity": ("quantity", qs)},
    )
    ds["max_abs_relative_difference"] = (
        "quantity",
        np.nanmax(
            np.abs(np.where(np.isfinite(arr["relative_difference"]), arr["relative_difference"], np.nan)), 0
        ),
        {"units": "1", "long_name": "largest |relative difference| over the scenes"},
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Beam vs continuum strip on the paper scenes",
            "model_interpretation": INTERPRETATION,
            "method": "both models from the same scene mapping and window",
        }
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
            "window_beam_value": (
                dims,
                beam,
                {"units": "1", "long_name": "beam model value (quantity's units)"},
            ),
            "window_continuum_value": (
                dims,
                cont,
                {"units": "1", "long_name": "continuum strip value (quantity's units)"},
            ),
            "window_agreement": (
                dims[:2],
                ok,
                {"units": "1", "long_name": "beam and continuum agree", "rule": WINDOW_RULE},
            ),
            "window_t_end": ("window_scene", t_end, {"units": "s", "long_name": "claim window of both runs"}),
        },
        coords={
            "window_scene": ("window_scene", scenes),
            "window_quantity": ("window_quantity", qs),
            "time_step": ("time_step", ["dt", "dt/2"], {"long_name": "explicit time step"}),
        },
    )


def increments_dataset(
    beam_mapping: Mapping, meshes, safety_factors, betas, duration: float = 0.65
) -> xr.Dataset:
    """Increment count of the continuum strip for ``duration`` (the paper's banner: 3 688 747 at 0.65 s)
    for each mesh x safety factor x stiffness damping, from its global stable step."""
    from ..fe.continuum import build_continuum, increments, stable_time_step

    p = _params(beam_mapping)
    fr = FrictionTable.paper_fig17()
    n = np.zeros((len(meshes), len(safety_factors), len(betas)))
    dtc = np.zeros((len(meshes), len(betas)))
    for i, (nx, ny) in enumerate(meshes):
        for k, beta in enumerate(betas):
            sc = build_continuum(p.beam, p.disc, p.contact, fr, nx=nx, ny=ny, damping_beta=beta)
            dtc[i, k] = stable_time_step(sc)
            for j, sf in enumerate(safety_factors):
                n[i, j, k] = increments(sc, duration, sf)
    ds = xr.Dataset(
        {
            "increments": (
                ("mesh", "safety_factor", "stiffness_damping"),
                n,
                {"units": "1", "long_name": f"explicit increments to reach {duration} s"},
            ),
            "stable_time_step": (
                ("mesh", "stiffness_damping"),
                dtc,
                {"units": "s", "long_name": "global stable time step 2/omega_max (damped)"},
            ),
            "mesh_nx": (
                "mesh",
                np.array([m[0] for m in meshes]),
                {"units": "1", "long_name": "elements along"},
            ),
            "mesh_ny": (
                "mesh",
                np.array([m[1] for m in meshes]),
                {"units": "1", "long_name": "elements across"},
            ),
        },
        coords={
            "mesh": ("mesh", [f"{a}x{b}" for a, b in meshes], {"long_name": "mesh (along x across)"}),
            "safety_factor": ("safety_factor", np.array(safety_factors, float), {"units": "1"}),
            "stiffness_damping": ("stiffness_damping", np.array(betas, float), {"units": "s"}),
        },
    )
    i0 = [f"{a}x{b}" for a, b in meshes].index("100x1") if (100, 1) in [tuple(m) for m in meshes] else 0
    j0 = int(np.argmin(np.abs(np.array(safety_factors, float) - 1.0)))
    ds["increments_0p65s_100x1"] = (
        (),
        float(n[i0, j0, 0]),
        {
            "units": "1",
            "long_name": "increments for 0.65 s, continuum 100x1, full stable step, no damping",
        },
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Explicit increment counts of the continuum strip",
            "model_interpretation": "plane-stress CPS4I-kind strip, lumped mass; global stable step",
            "method": "dt = safety_factor * 2/omega_max (sqrt(1+xi^2)-xi); increments = ceil(duration/dt)",
        }
    )
    return ds
