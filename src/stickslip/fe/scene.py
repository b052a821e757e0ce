"""Build a beam-on-disc scene from parameters: full FE system, contact law, and the reduced model."""

from __future__ import annotations

from dataclasses import dataclass

from .beam import BeamModel, assemble_beam
from .contact import ContactGeometry, contact_geometry
from .explicit import ContactLaw, System, static_state
from .params import FrictionTable, SceneParams


@dataclass(frozen=True)
class BuiltScene:
    params: SceneParams
    beam: BeamModel
    geometry: ContactGeometry
    system: System
    law: ContactLaw


def build_system(beam: BeamModel, geom: ContactGeometry, label: str = "full") -> System:
    return System(beam.M, beam.K, beam.f, geom.c_x, geom.c_y, geom.c_n, geom.c_t, label)


def propped_normal_force(p: SceneParams) -> float:
    """Static contact reaction [N] of the free (Section 9) configuration; used as the held normal load
    of the Section 10 scene whose transverse motion is constrained."""
    free = assemble_beam(p.beam)
    geom = contact_geometry(free, p.contact, p.disc.diameter / 2, p.disc.direction)
    law = ContactLaw("kinematic", FrictionTable.paper_fig17(), 0.0)
    return static_state(build_system(free, geom), law)[1]


def build_scene(p: SceneParams, friction: FrictionTable) -> BuiltScene:
    fixed = p.contact.method == "fixed_normal"
    beam = assemble_beam(p.beam, constrain_transverse=fixed)
    geom = contact_geometry(beam, p.contact, p.disc.diameter / 2, p.disc.direction)
    system = build_system(beam, geom)
    law = ContactLaw(
        p.contact.method,
        friction,
        p.disc.surface_speed,
        penalty_stiffness=p.contact.penalty_stiffness if p.contact.method == "penalty" else 0.0,
        fixed_normal_force=propped_normal_force(p) if fixed else 0.0,
    )
    return BuiltScene(p, beam, geom, system, law)
