"""CalculiX as a peer of the continuum strip: modes and static self-weight states, three ways.

The strip of the FE config (``fe.defaults.beam``, mesh ``fe.peer.mesh``: the paper's 100 x 1), clamped at
x = 0, its own weight the load, with the free end either free or propped at its lower corner (the contact
held on a disc at angle 0), computed by

* the closed forms of ``fe.mechanics`` (Euler-Bernoulli beam),
* the project's continuum (``fe.continuum``: QM6 plane-stress quads, lumped mass), and
* CalculiX (``ccx``) on the C3D8I deck of ``fe.abaqus_deck.linear_deck`` (consistent mass).

Quantities: the first three in-plane bending frequencies free and propped, the free tip deflection, and of
the propped strip the tip rotation, both free-end corners' horizontal offsets and the prop's reaction.
"""

from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np
import scipy.sparse.linalg as spla
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe import mechanics
from ..fe.abaqus_deck import LINEAR_ELEMENT, LINEAR_ELEMENT_REASON, linear_deck
from ..fe.continuum import build_continuum, natural_frequencies, static_state
from ..fe.params import BeamParams, ContactParams, DiscParams, FrictionTable
from ..fe.quantities import cf_attrs
from ..schema.fe import FePeer
from ..validation.calculix import CalculixError, mode_blocks, parse_dat, run_ccx, static_block

N_BENDING = 3
#: modes ccx computes to find the first N_BENDING in-plane bending ones among them
N_MODES_CCX = 8

#: quantity -> (units, long name)
_PROPPED = "tip propped at its lower corner"
QUANTITIES = {
    **{f"free_f{k}": ("Hz", f"bending frequency {k}, free tip") for k in range(1, N_BENDING + 1)},
    **{f"propped_f{k}": ("Hz", f"bending frequency {k}, {_PROPPED}") for k in range(1, N_BENDING + 1)},
    "free_tip_deflection": ("mm", "static self-weight tip deflection, free tip (mean of the end corners)"),
    "propped_tip_rotation": ("rad", f"static end-section rotation (counter-clockwise), {_PROPPED}"),
    "propped_lower_corner_ux": ("mm", f"static horizontal offset of the free-end lower corner, {_PROPPED}"),
    "propped_upper_corner_ux": ("mm", f"static horizontal offset of the free-end upper corner, {_PROPPED}"),
    "propped_reaction": ("N", f"static prop reaction, {_PROPPED}"),
}
MODELS = ("closed_form", "continuum", "calculix")
PAIRS = (("calculix", "continuum"), ("calculix", "closed_form"), ("continuum", "closed_form"))


def closed_form_values(beam: BeamParams) -> dict:
    q = mechanics.distributed_weight(beam.rho, beam.area, beam.g)
    EI, L, h = beam.E * beam.inertia, beam.length, beam.thickness
    rho_a = beam.rho * beam.area
    theta = mechanics.tip_rotation(q, L, EI, "propped")
    out = {
        f"free_f{k + 1}": f
        for k, f in enumerate(mechanics.bending_frequencies(EI, rho_a, L, "cantilever", N_BENDING))
    }
    out |= {
        f"propped_f{k + 1}": f
        for k, f in enumerate(mechanics.bending_frequencies(EI, rho_a, L, "propped", N_BENDING))
    }
    out |= {
        "free_tip_deflection": -q * L**4 / (8.0 * EI),
        "propped_tip_rotation": theta,
        "propped_lower_corner_ux": mechanics.corner_displacement(theta, h),
        "propped_upper_corner_ux": -mechanics.corner_displacement(theta, h),
        "propped_reaction": mechanics.propped_reaction(q, L),
    }  # fmt: skip
    return {k: float(v) for k, v in out.items()}


def continuum_values(beam: BeamParams, nx: int, ny: int) -> dict:
    """The continuum strip, its tip propped by the kinematic contact held at angle 0 (no friction acts in a
    static or modal state with a vertical normal)."""
    scene = build_continuum(
        beam, DiscParams(surface_speed_mm_s=0.0), ContactParams(), FrictionTable.paper_fig17(), nx=nx, ny=ny
    )
    mesh = scene.mesh
    lo, up = 2 * int(mesh.lower[-1]), 2 * int(mesh.upper[-1])
    axial = float(mechanics.axial_frequencies(beam.E, beam.rho, beam.length, 1)[0])
    out = {}
    for support, held in (("free", False), ("propped", True)):
        f = natural_frequencies(scene, N_BENDING, contact_held=held)
        if f[-1] >= 0.9 * axial:  # the first N_BENDING modes are bending only below the first axial mode
            raise ValueError(f"mesh: bending mode {N_BENDING} ({f[-1]:.4g} Hz) reaches the first axial mode")
        out |= {f"{support}_f{k + 1}": float(v) for k, v in enumerate(f)}
    fr = scene.free
    u = np.zeros(mesh.n_dof)
    u[fr] = spla.spsolve(scene.K[fr][:, fr].tocsc(), scene.f[fr])
    out["free_tip_deflection"] = 0.5 * float(u[lo + 1] + u[up + 1])
    u, normal = static_state(scene)
    out["propped_tip_rotation"] = float(u[lo] - u[up]) / beam.thickness
    out["propped_lower_corner_ux"] = float(u[lo])
    out["propped_upper_corner_ux"] = float(u[up])
    out["propped_reaction"] = float(normal)
    return out


def _mean(rows: Mapping) -> np.ndarray:
    return np.mean(np.array([rows[n] for n in sorted(rows)]), axis=0)


def bending_modes(dat, scene: str, n: int = N_BENDING) -> list[float]:
    """The first ``n`` in-plane bending frequencies of a frequency step: a mode is in-plane bending when the
    end section's vertical motion or rotation exceeds both its mean axial motion and any out-of-plane
    motion (the corners' displacements printed per mode)."""
    if not dat.frequencies:
        raise CalculixError(f"{scene}: the .dat has no eigenvalue table")
    freqs = dat.frequencies[-1]
    low, up = mode_blocks(dat, "TIPLOW"), mode_blocks(dat, "TIPUP")
    bending = []
    for k, f in enumerate(freqs, start=1):
        if k not in low or k not in up:
            raise CalculixError(f"{scene}: no corner displacements printed for mode {k}")
        a, b = _mean(low[k]), _mean(up[k])
        vert_rot = max(abs(a[1]), abs(b[1]), abs(a[0] - b[0]) / 2)
        if vert_rot > abs(a[0] + b[0]) / 2 and vert_rot > max(abs(a[2]), abs(b[2])):
            bending.append(f)
    if len(bending) < n:
        raise CalculixError(
            f"{scene}: only {len(bending)} in-plane bending modes among the {len(freqs)} computed"
        )
    return bending[:n]


def calculix_values(beam: BeamParams, nx: int, ny: int, workdir=None) -> tuple[dict, dict]:
    """Run the free and propped decks with ccx; (values, decks by name). ``workdir``: keep ccx's files there.

    The prop's reaction is ccx's printed RF plus the load ccx applies directly at the prop's nodes (ccx
    reports a constrained DOF's reaction net of the external load on that DOF: for a brick's corner node
    the self-weight share rho g V_e / 8)."""
    out, decks = {}, {}
    for support in ("free", "propped"):
        name = f"peer_{support}"
        deck = decks[name] = linear_deck(
            beam, nx, ny, support, N_MODES_CCX, title=f"stickslip CalculiX peer: {support} tip"
        )
        dat = parse_dat(run_ccx(deck, name, workdir=None if workdir is None else f"{workdir}/{name}"))
        out |= {f"{support}_f{k + 1}": f for k, f in enumerate(bending_modes(dat, name))}
        low, up = (
            _mean(static_block(dat, "displacements", "TIPLOW", name)),
            _mean(static_block(dat, "displacements", "TIPUP", name)),
        )
        if support == "free":
            out["free_tip_deflection"] = float(low[1] + up[1]) / 2
        else:
            out["propped_tip_rotation"] = float(low[0] - up[0]) / beam.thickness
            out["propped_lower_corner_ux"] = float(low[0])
            out["propped_upper_corner_ux"] = float(up[0])
            rf = static_block(dat, "total force", "PROP", name)[0]
            own = 2 * beam.rho * beam.g * beam.width * (beam.length / nx) * (beam.thickness / ny) / 8.0
            out["propped_reaction"] = float(rf[1]) + own
    return out, decks  # fmt: skip


def relative_difference(a: float, b: float) -> float:
    """(a - b) / |b|."""
    return float((a - b) / abs(b)) if b != 0 else float("nan")


def peer_rows(values: Mapping[str, Mapping[str, float]], tolerance: float) -> list[dict]:
    """One row per quantity: unit, the three values, the three relative differences, within tolerance,
    the element and why."""
    rows = []
    for q, (unit, long_name) in QUANTITIES.items():
        row = {"quantity": q, "unit": unit, **{m: values[m][q] for m in MODELS}}
        for a, b in PAIRS:
            row[f"rel_diff_{a}_{b}"] = relative_difference(values[a][q], values[b][q])
        row["within_tolerance"] = all(abs(row[f"rel_diff_{a}_{b}"]) <= tolerance for a, b in PAIRS)
        row["calculix_element"] = LINEAR_ELEMENT
        row["element_reason"] = LINEAR_ELEMENT_REASON
        row["long_name"] = long_name
        rows.append(row)
    return rows


def peer_dataset(rows: list[dict], beam: BeamParams, nx: int, ny: int, tolerance: float) -> xr.Dataset:
    """Per quantity the three values (scalars ``<quantity>_<model>``, in the quantity's units) and, over
    dimension ``quantity``, the relative differences; ``max_abs_rel_diff`` and ``peers_agree`` (1 when
    every pair agrees within ``tolerance`` on every quantity)."""
    data = {}
    for r in rows:
        for m in MODELS:
            data[f"{r['quantity']}_{m}"] = cf_variable(
                (), r[m], r["unit"], f"{r['long_name']}: {m.replace('_', ' ')}"
            )
    quantities = [r["quantity"] for r in rows]
    for a, b in PAIRS:
        data[f"rel_diff_{a}_{b}"] = cf_variable(
            "quantity",
            [r[f"rel_diff_{a}_{b}"] for r in rows],
            "1",
            f"relative difference ({a} - {b}) / |{b}|",
        )
    worst = max(abs(r[f"rel_diff_{a}_{b}"]) for r in rows for a, b in PAIRS)
    data["max_abs_rel_diff"] = cf_variable(
        (), worst, "1", "largest |relative difference| over quantities and pairs"
    )
    data["peers_agree"] = cf_variable(
        (),
        np.int8(worst <= tolerance),
        "1",
        f"1 if closed form, continuum and CalculiX agree within {tolerance:g} on all",
        tolerance=tolerance,
    )
    ds = xr.Dataset(data, coords={"quantity": ("quantity", np.array(quantities, dtype=object))})
    ds["quantity_unit"] = xr.DataArray(
        [r["unit"] for r in rows], dims="quantity", attrs={"long_name": "unit of each quantity"}
    )
    ds.attrs.update(
        cf_attrs(
            "CalculiX peer of the continuum strip: modes and self-weight states",
            parameters=json.dumps({"beam": beam.__dict__, "mesh": [nx, ny], "tolerance": tolerance}),
            model_interpretation=(
                f"strip {beam.length:g} x {beam.thickness:g} mm, width {beam.width:g} mm, clamped at x = 0, "
                "own weight; tip free, or propped at its free-end lower corner (u_y = 0, the contact on a "
                "disc at angle 0). "
                f"Closed form: Euler-Bernoulli. Continuum: {nx} x {ny} QM6 plane-stress quads, lumped mass. "
                f"CalculiX: {nx} x {ny} x 1 {LINEAR_ELEMENT} bricks, u_z = 0 on one face, consistent mass: "
                + LINEAR_ELEMENT_REASON
            ),
            method="linear static and eigenvalue analyses; ccx on the decks of stickslip.fe.abaqus_deck",
        )
    )
    return ds


def peer_study(beam: BeamParams, peer: FePeer, workdir=None) -> tuple[list[dict], xr.Dataset, dict]:
    """(table rows, dataset, linear decks by name) of the FE config's strip."""
    (nx, ny), tolerance = peer.mesh, peer.tolerance
    ccx, decks = calculix_values(beam, nx, ny, workdir)
    values = {
        "closed_form": closed_form_values(beam),
        "continuum": continuum_values(beam, nx, ny),
        "calculix": ccx,
    }
    rows = peer_rows(values, tolerance)
    return rows, peer_dataset(rows, beam, nx, ny, tolerance), decks
