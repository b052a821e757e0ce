"""CalculiX (``ccx`` 2.20) variant of a Section 9-12 scene deck: pure functions, text out.

ccx cannot read the ABAQUS/Explicit scene decks of ``fe.abaqus_deck``: it has no analytical rigid surfaces
(``*SURFACE, TYPE=SEGMENTS`` and ``*RIGID BODY, ANALYTICAL SURFACE``), no kinematic contact (only penalty
contact), no slip-rate-dependent friction (``*FRICTION`` takes one mu and a stick slope; a mu(slip rate)
table is silently read as its first row) and no explicit-dynamics data line of ABAQUS's form. The variant
keeps what ccx can run of the same scene:

* **Strip**: the continuum's nx x ny mesh extruded one element through the width b as C3D8I bricks (the
  peer's element, ``abaqus_deck.LINEAR_ELEMENT``), u_z = 0 on the face z = 0 (in-plane motion, plane
  stress), clamped at x = 0; Section 10 (``fixed_normal``) holds u_y = 0 on the upper face.
* **Disc -> moving block**: one C3D8 brick whose top face is the disc's tangent plane at the contact point
  (the free-end lower corner, normal tilted by the contact angle towards the clamp), every node of it
  prescribed to translate at the disc's surface velocity V t (clockwise disc: t = (n_y, -n_x)). Over the
  few milliseconds a ccx run covers the disc surface moves V t_end (at most 0.1 mm at 19.9 mm/s x 5 ms)
  and a 12.5 mm disc falls away from its tangent plane by (V t_end)^2 / (2 R) < 0.4 um at the contact, so
  the flat block is the disc to within 0.4 um; the block's reaction force (all its nodes prescribed, no
  strain) is the contact force on the strip, reversed.
* **Contact**: node-to-surface penalty (ccx's ``*CONTACT PAIR, TYPE=NODE TO SURFACE``), slave = the
  free-end lower corner nodes (the project's contact node, both z), master = the block's top face, linear
  pressure-overclosure. The scene's penalty stiffness for Section 11, a stiff penalty
  (``KINEMATIC_STAND_IN`` N/mm) standing in for ABAQUS's kinematic contact in the others.
* **Friction**: one constant mu (``*FRICTION``: mu, stick slope), default the table's kinetic plateau.
* **Time**: ccx's implicit ``*DYNAMIC`` (HHT alpha), fixed increment, gravity switched on at t = 0 on the
  undeformed strip touching the block (the drop start of ABAQUS/Explicit).

Units as ``fe.params``: mm, s, N, t (tonne), MPa.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Annotated

import numpy as np
from pydantic import Field

from ..model.params import Count, NonNegative, ParameterError, Positive, checked_arguments
from .abaqus_deck import LINEAR_ELEMENT, _elements, _material, _nodes, _nset, _num, brick_strip
from .params import BeamParams, ContactParams, SceneParams

#: penalty stiffness [N mm-1 at the contact node] standing in for ABAQUS's kinematic contact (ccx has none):
#: 50 x the strip's axial stiffness EA/L = 2100 N/mm, so the contact spring adds < 1 % compliance
KINEMATIC_STAND_IN = 1.0e5
#: stick slope of ccx's friction [N mm-1 at the contact node]: the tangential spring while sticking
#: (ccx has no exact stick), the same stiffness as the normal penalty unless given
DEFAULT_MU = 0.4  #: the Fig. 17 table's kinetic plateau (mu above 0.6 mm/s relative speed)
#: half-length of the block's top face along the tangent [mm] and its depth [mm]
BLOCK_HALF_LENGTH = 2.0
BLOCK_DEPTH = 1.0
#: the strip's nodes out of plane reach z = 0 and z = b; the block overhangs both by this fraction of b
BLOCK_OVERHANG = 0.5
#: the window and largest increment of the ccx variants rule ``fe_decks`` writes: half a millisecond of the
#: drop start (ccx 2.20 takes ~60 s of CPU per simulated millisecond on the 100 x 1 strip, its implicit
#: contact dynamics cutting the increment to ~0.3-1 us by its energy and impact checks; on the transient
#: peer's deck it stalls at 0.574 ms, "too many cutbacks", so longer windows are not offered)
CCX_T_END = 5.0e-4
CCX_MAX_INCREMENT = 1.0e-6
#: HHT alpha of ccx's *DYNAMIC (0: trapezoidal rule, no numerical damping; ccx's default is -0.05)
DEFAULT_ALPHA = -0.05


def contact_frame(beam: BeamParams, contact: ContactParams, direction: str) -> tuple:
    """(contact point (x, y), outward disc normal n, disc surface velocity direction t), as
    ``fe.contact.contact_geometry`` and ``fe.continuum.build_continuum``."""
    a = math.radians(contact.angle_deg)
    sgn = 1.0 if direction == "clockwise" else -1.0
    n = np.array([-math.sin(a), math.cos(a)])
    t = sgn * np.array([n[1], -n[0]])
    return np.array([beam.length, -beam.thickness / 2.0]), n, t


def block_nodes(beam: BeamParams, contact: ContactParams, direction: str) -> np.ndarray:
    """(8, 3) nodes of the block brick in C3D8 order: at z0 the two bottom corners (``BLOCK_DEPTH`` below
    the tangent plane) then the two top corners (on it), counter-clockwise seen from +z; then the same at
    z1. Its face S5 (nodes 3-7-8-4) is the top face."""
    p, n, _ = contact_frame(beam, contact, "clockwise")
    along = np.array([n[1], -n[0]])  # along the tangent plane, +x at angle 0
    h = BLOCK_HALF_LENGTH
    top = [p - h * along, p + h * along]
    bot = [q - BLOCK_DEPTH * n for q in top]
    z0, z1 = -BLOCK_OVERHANG * beam.width, (1 + BLOCK_OVERHANG) * beam.width
    quad = [bot[0], bot[1], top[1], top[0]]  # counter-clockwise in the x-y plane
    return np.array([[x, y, z0] for x, y in quad] + [[x, y, z1] for x, y in quad])


@checked_arguments(
    nx=Count,
    ny=Count,
    t_end=Positive,
    dt=Positive,
    mu=NonNegative,
    penalty_stiffness=Positive | None,
    stick_slope=Positive | None,
    alpha=Annotated[float, Field(ge=-1.0 / 3.0, le=0.0)],  # ccx's HHT range
    output_every=Count,
)
def ccx_scene_deck(
    name: str,
    mapping: Mapping,
    nx: int,
    ny: int,
    *,
    t_end: float,
    dt: float,
    mu: float = DEFAULT_MU,
    stick_slope: float | None = None,
    penalty_stiffness: float | None = None,
    alpha: float = DEFAULT_ALPHA,
    output_every: int = 1,
) -> str:
    """The ccx variant of scene ``name`` (merged scene mapping, ``studies.fe_config.scene_mapping``) on the
    continuum's nx x ny mesh: ``t_end`` simulated seconds in fixed increments ``dt`` [s]; one friction
    coefficient ``mu``; ``penalty_stiffness`` [N mm-1 at the contact node] default the scene's (Section 11)
    or ``KINEMATIC_STAND_IN``; ``stick_slope`` [N mm-1] default the penalty stiffness; tip displacements
    and the block's reaction force printed every ``output_every`` increments."""
    if not dt <= t_end:
        raise ParameterError(f"dt: must lie in (0, t_end = {t_end!r}], got {dt!r}")
    p = SceneParams.from_mapping(mapping)
    beam, disc, contact = p.beam, p.disc, p.contact
    held = contact.method == "fixed_normal"
    if penalty_stiffness is None:
        penalty_stiffness = contact.penalty_stiffness if contact.method == "penalty" else KINEMATIC_STAND_IN
    if stick_slope is None:
        stick_slope = penalty_stiffness

    s = brick_strip(beam, nx, ny)
    n_strip = s.nodes.shape[0]
    blk = block_nodes(beam, contact, disc.direction)
    blk_ids = np.arange(n_strip + 1, n_strip + 9)
    blk_el = len(s.elements) + 1
    _, n, t = contact_frame(beam, contact, disc.direction)
    vel = disc.surface_speed * t
    n_slave = s.tip_lower.size
    # ccx's linear pressure-overclosure on a nodal slave surface acts per slave node (unit area): the
    # project's stiffness at the contact node is shared by the corner's nodes through the width
    k_node, lam_node = penalty_stiffness / n_slave, stick_slope / n_slave
    upper = np.nonzero(np.isclose(s.nodes[:, 1], beam.thickness / 2.0))[0] + 1
    out = [
        "*HEADING",
        f"stickslip scene {name}, CalculiX variant: strip {beam.length:g} x {beam.thickness:g} x "
        f"{beam.width:g} mm on a block translating at {disc.surface_speed:.6g} mm/s",
        "** Written by stickslip.fe.ccx_deck.ccx_scene_deck: what ccx 2.20 can run of the ABAQUS/Explicit",
        f"** scene deck results/fe/inp/{name}.inp. Units: mm, s, N, t (tonne), MPa.",
        f"** Element {LINEAR_ELEMENT} (nx x ny = {nx} x {ny}, one through the width, u_z = 0 on z = 0: plane",
        "**   stress); ccx has no CPS4R/CPS4I for explicit contact runs.",
        "** Disc -> block: ccx has no analytical rigid surface; one C3D8 brick whose top face is the",
        f"**   disc's tangent plane at the free-end lower corner (contact angle {contact.angle_deg:g} deg),",
        f"**   every node moving at the surface velocity ({_num(vel[0])}, {_num(vel[1])}) mm/s",
        f"**   ({disc.direction} disc of D {disc.diameter:g} mm); over {t_end:g} s the disc surface leaves",
        "**   its tangent plane by",
        f"**   {(disc.surface_speed * t_end) ** 2 / disc.diameter:.2g} mm at the contact.",
        "** Contact: ccx has penalty contact only; node-to-surface, slave = the free-end lower corner,",
        f"**   linear pressure-overclosure {penalty_stiffness:g} N/mm at the contact node"
        + (" (the scene's penalty)" if contact.method == "penalty" else " (stand-in for kinematic contact)")
        + f", {_num(k_node)} per slave node.",
        f"** Friction: ccx has no slip-rate-dependent friction; one mu = {mu:g} (not the Fig. 17 table),",
        f"**   stick slope {stick_slope:g} N/mm at the contact node (ccx has no exact stick).",
        f"** Time: implicit *DYNAMIC (HHT alpha = {alpha:g}), fixed increment {dt:g} s, {t_end:g} s; gravity",
        "**   from t = 0 on the undeformed strip touching the block (drop start); no material damping.",
        "** Output (.dat): free-end lower/upper corner U every increment printed; block reaction RF totals",
        "**   (= minus the contact force on the strip); strip kinetic and strain energy totals.",
        "*NODE, NSET=NALL",
    ]
    out += [*_nodes(s.nodes), "*NODE, NSET=BLOCKN", *_nodes(blk, blk_ids)]
    out += [f"*ELEMENT, TYPE={LINEAR_ELEMENT}, ELSET=STRIP", *_elements(s.elements)]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=BLOCK", *_elements([blk_ids], blk_el)]
    out += _nset("CLAMP", s.clamp) + _nset("ZFACE", s.face_z0)
    out += _nset("TIPLOW", s.tip_lower) + _nset("TIPUP", s.tip_upper)
    if held:
        out += _nset("UPPER", upper)
    out += ["*SURFACE, TYPE=NODE, NAME=CORNER", "TIPLOW"]
    # C3D8 face S5 = nodes 3-7-8-4: the top face (nodes 3, 4 on the tangent plane at z0, 7, 8 at z1)
    out += ["*SURFACE, TYPE=ELEMENT, NAME=BLOCKTOP", f"{blk_el}, S5"]
    out += [*_material(beam), "*SOLID SECTION, ELSET=STRIP, MATERIAL=STEEL"]
    out += [*_material(beam, name="BLOCKMAT"), "*SOLID SECTION, ELSET=BLOCK, MATERIAL=BLOCKMAT"]
    out += [
        "*SURFACE INTERACTION, NAME=SI",
        "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
        _num(k_node),
        "*FRICTION",
        f"{_num(mu)}, {_num(lam_node)}",
        "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE",
        "CORNER, BLOCKTOP",
    ]
    out += ["*BOUNDARY", "CLAMP, 1, 3", "ZFACE, 3, 3"]
    if held:
        out += ["UPPER, 2, 2"]
    out += ["*INITIAL CONDITIONS, TYPE=VELOCITY"]
    out += [f"BLOCKN, {k + 1}, {_num(vel[k])}" for k in (0, 1)]
    out += ["*AMPLITUDE, NAME=ON", f"0., 1., {_num(t_end)}, 1."]
    out += ["*AMPLITUDE, NAME=SLIDE", f"0., 0., {_num(t_end)}, {_num(t_end)}"]
    out += [
        "*STEP, NLGEOM, INC=1000000",
        f"*DYNAMIC, ALPHA={_num(alpha)}",
        f"{_num(dt)}, {_num(t_end)}, {_num(dt * 1e-4)}, {_num(dt)}",
        "*BOUNDARY, AMPLITUDE=SLIDE",
        f"BLOCKN, 1, 1, {_num(vel[0])}",
        f"BLOCKN, 2, 2, {_num(vel[1])}",
        "*BOUNDARY",
        "BLOCKN, 3, 3, 0.",
        "*DLOAD, AMPLITUDE=ON",
        f"STRIP, GRAV, {_num(beam.g)}, 0., -1., 0.",
        f"*NODE PRINT, NSET=TIPLOW, FREQUENCY={output_every}",
        "U",
        "*NODE PRINT, NSET=TIPUP",
        "U",
        "*NODE PRINT, NSET=BLOCKN, TOTALS=ONLY",
        "RF",
        "*EL PRINT, ELSET=STRIP, TOTALS=ONLY",
        "ELKE, ELSE",
        "*END STEP",
    ]
    return "\n".join(out) + "\n"
