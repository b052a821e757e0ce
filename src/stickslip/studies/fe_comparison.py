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

from ..fe.metrics import trajectory_metrics
from ..fe.params import FrictionTable
from ..fe.scene import SceneParams
from .fe import INTERPRETATION, result_dataset, run_scene

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
    """Pure build: run the continuum strip for the scene mapping; same variables as the beam's dataset."""
    from ..fe.continuum import integrate_continuum

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
        }
    )
    return ds


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


def comparison_rows(
    continuum: Mapping[str, xr.Dataset],
    beam: Mapping[str, Mapping],
    notes: Mapping[str, str] | None = None,
    floors: Mapping[str, Mapping] | None = None,
) -> list[dict]:
    """One row per (scene, quantity): continuum, beam, relative difference, the noise floor (``floors``
    [scene][quantity], 0 when not measured), the agreement flag and its rule, and the config's note for
    the scene (or the quantity) where they do not agree."""
    notes = notes or {}
    floors = floors or {}
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
                    "note": ""
                    if ok
                    else " ".join(str(notes[k]) for k in (f"{scene}.{q}", scene, q) if k in notes),
                }
            )
    return rows


def comparison_dataset(rows: list[dict], continuum: Mapping[str, xr.Dataset], beam: Mapping[str, Mapping]):
    """The comparison table as a dataset (scene x quantity), with the CPU times of both models."""
    scenes = list(continuum)
    qs = list(QUANTITIES)
    keys = ("continuum", "beam", "relative_difference", "noise_floor", "agreement")
    arr = {k: np.full((len(scenes), len(qs)), np.nan) for k in keys}
    for r in rows:
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
    return ds


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
