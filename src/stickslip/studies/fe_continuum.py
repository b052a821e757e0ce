"""The continuum strip (the paper's kind of model) run on a beam scene mapping: its scene, its dataset,
and its run over a claim's window with the step-halving member.

Both models are built from the same merged scene mapping. The beam's Section 10 scene (``fixed_normal``:
transverse motion suppressed, normal force held) is run in the continuum as the paper describes it:
kinematic contact with the upper face held vertically (``constrain_upper_face``).
"""

from __future__ import annotations

import json
from collections.abc import Mapping

import xarray as xr

from ..catalogue import fe_continuum_window
from ..ensemble import EnsembleSpec, ensemble_dataset, step_member_values
from ..fe.metrics import trajectory_metrics
from ..fe.modes import mode_growth
from ..fe.params import FrictionTable, SceneParams
from ..fe.quantities import INTERPRETATION, cf_attrs
from ..fe.step_halving import HALF_STEP, apply_step_halving
from ..schema.fe import FeOutput
from .fe_packing import result_dataset


def continuum_scene_from_mapping(mapping: Mapping, friction: FrictionTable, nx: int, ny: int):
    """The continuum scene of a beam scene mapping (same geometry reading, damping and contact law)."""
    from ..fe.continuum import build_continuum

    p = SceneParams.from_mapping(mapping)
    contact = p.contact
    upper = contact.method == "fixed_normal"
    if upper:
        contact = contact.model_copy(update={"method": "kinematic"})
    return build_continuum(
        p.beam,
        p.disc,
        contact,
        friction,
        nx=nx,
        ny=ny,
        output_node=p.contact.output_node,
        damping_beta=p.solver.stiffness_damping,
        constrain_upper_face=upper,
    )


def continuum_dataset(
    mapping: Mapping, friction: FrictionTable, *, nx: int = 100, ny: int = 1, name: str = ""
) -> xr.Dataset:
    """Pure build: run the continuum strip for the scene mapping; the beam dataset's trajectory metrics, and
    the growth of the strip's own first contact-held mode at node 1 (the beam's first_mode_* variables
    but the linear estimate)."""
    from ..fe.continuum import integrate_continuum, natural_frequencies

    p = SceneParams.from_mapping(mapping)
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
    out = FeOutput.model_validate(mapping.get("output", {}))
    ds = result_dataset(r, m, windows=out.windows, bin_width=out.bin_width)
    ds.attrs.update(
        cf_attrs(
            f"Continuum strip {nx}x{ny} on rotating rigid disc, scene {name}".strip(),
            scene=name,
            parameters=json.dumps({"mapping": mapping, "nx": nx, "ny": ny}, default=str),
            model_interpretation=(
                "plane-stress strip, Q4 with incompatible modes (CPS4I kind), lumped mass, node-to-surface "
                "contact of the lower face on the rigid disc; Section 10 as upper face held vertically. "
                "Other choices as the beam model: " + INTERPRETATION
            ),
            method=f"explicit central difference, dt={r.dt:.6g} s (stable limit {r.dt_crit:.6g} s)",
            diverged=int(r.extra.get("diverged", False)),
            t_end=float(p.solver.t_end),
        )
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
