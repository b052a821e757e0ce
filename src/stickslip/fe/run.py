"""One run of a built beam-on-disc scene: the explicit integration (full model, or Craig-Bampton reduced)
and the scalar metrics of its trajectory (stickslip.fe.quantities names their units)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .explicit import integrate
from .metrics import trajectory_metrics, trend_sign, window_envelope
from .modes import first_mode_growth, midspan_dofs, midspan_motion, natural_frequencies
from .reduced import contact_boundary, craig_bampton
from .scene import BuiltScene


def reduced_system(scene: BuiltScene, reduced: Mapping):
    """The scene's Craig-Bampton reduced system (``reduced``: n_bending_modes, n_axial_modes)."""
    mask = (scene.beam.free % 3) == 0
    system, _ = craig_bampton(
        scene.system,
        contact_boundary(scene.system),
        int(reduced.get("n_bending_modes", 4)),
        mask,
        int(reduced.get("n_axial_modes", 1)),
    )
    return system


def integrate_scene(
    scene: BuiltScene,
    *,
    duration: float | None = None,
    reduced: Mapping | None = None,
    progress=None,
    midspan: bool = False,
):
    """Integrate the scene over ``duration`` (default: its solver's t_end). ``midspan`` (full model only):
    also record the mid-span node's motion (``result.extra['midspan']``, the rest of the state dropped)."""
    sp = scene.params.solver
    system = reduced_system(scene, reduced) if reduced else scene.system
    record_midspan = midspan and not reduced
    mid = midspan_dofs(scene) if record_midspan else np.zeros(0, np.int64)
    r = integrate(
        system,
        scene.law,
        duration or sp.t_end,
        safety_factor=float((reduced or {}).get("safety_factor", sp.safety_factor)),
        output_interval=sp.output_dt,
        initial_state=sp.initial_state,
        mass_damping=sp.mass_damping,
        stiffness_damping=sp.stiffness_damping,
        progress=progress,
        record_state=record_midspan,
        record_dofs=mid[mid >= 0] if record_midspan else None,
    )
    if record_midspan:
        r.extra["midspan"] = midspan_motion(scene, r, mid)
        r.q_samples = r.v_samples = None  # only the mid-span series are kept
    return r


def run_metrics(scene: BuiltScene, r) -> dict:
    """The run's scalar metrics: node 1's trajectory metrics against the contact-held natural frequencies,
    the first mode's growth (its amplitude series goes to ``r.extra['first_mode_amplitude']``), the
    mid-span node's where recorded, the disc speed and the trends of the envelopes."""
    nat = natural_frequencies(scene)
    m = trajectory_metrics(r, nat)
    growth, r.extra["first_mode_amplitude"] = first_mode_growth(scene, r, nat[0], scene.params.solver)
    m.update(growth)
    if "midspan" in r.extra:
        y, vy = r.extra["midspan"]["vertical"]
        half = r.t >= 0.5 * r.t[-1]
        m["midspan_vertical_amplitude"] = float(0.5 * (y[half].max() - y[half].min()))
        m["midspan_max_abs_vertical_velocity"] = float(np.abs(vy).max())
    m["disc_surface_speed"] = scene.params.disc.surface_speed
    _, evx = window_envelope(r.t, r.vx)
    _, evy = window_envelope(r.t, r.vy)
    _, ex = window_envelope(r.t, r.x - r.x[0])
    m["horizontal_velocity_trend"] = trend_sign(evx)
    m["vertical_velocity_trend"] = trend_sign(evy)
    m["horizontal_displacement_trend"] = trend_sign(ex)
    return m
