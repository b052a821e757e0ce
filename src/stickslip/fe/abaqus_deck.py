"""ABAQUS-style input decks of the strip on the rigid disc (paper Sections 8-12): pure functions, text out.

Two kinds of deck, both from the same parameters as the continuum strip (``fe.continuum``: geometry, material,
mesh, clamp, gravity, contact point):

* **Linear decks** (``linear_deck``) that CalculiX (``ccx``) and ABAQUS/Standard both run: the strip as
  nx x ny x 1 C3D8I bricks (incompatible modes: ccx has no plane-stress CPS4I; plain C3D8/CPS4 lock in
  bending at one element through the thickness, reduced integration hourglasses), u_z = 0 on the face
  z = 0 (in-plane motion, free Poisson contraction through the width: plane stress), clamped at x = 0; a
  ``*FREQUENCY`` step and a static self-weight step, with the tip free or the free-end lower corner propped
  (u_y = 0, the contact held on a disc at angle 0).
* **Scene decks** (``scene_deck``): the paper's ABAQUS/Explicit model of one Section 9-12 scene: 2-D plane
  stress strip (CPS4R with enhanced hourglass control, ABAQUS/Explicit's stand-in for CPS4I, which it does
  not offer), lumped mass, an analytical rigid disc turned about its reference node, the lower face the
  slave surface of a contact pair (kinematic or penalty), friction mu(slip rate) from the Fig. 17 table
  (the paper's Fig. 18 contact property), gravity from t = 0 (the drop start), node-1 history output.

Units as ``fe.params``: mm, s, N, t (tonne), MPa; so density in t mm-3, gravity 9810 mm s-2.
``read_deck`` parses a deck back (keywords, nodes, elements, friction data) for the tests and the runner.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..model.params import Count, checked_arguments
from .continuum import strip_mesh
from .params import BeamParams, ContactParams, DiscParams, FrictionTable, SceneParams

#: the brick of the linear decks and why (printed into each deck and the peer table)
LINEAR_ELEMENT = "C3D8I"
LINEAR_ELEMENT_REASON = (
    "8-node brick with incompatible modes, one element through the width, u_z = 0 on one face: exact pure "
    "bending of a rectangular element, as the continuum's QM6 (ccx has no CPS4I; CPS4 locks at 100 x 1: "
    "+24 % frequency, -35 % deflection; CPS4R hourglasses; CPS8 is 2.6 % stiff through nu)"
)
#: the plane-stress element of the scene decks and why
SCENE_ELEMENT = "CPS4R"
SCENE_ELEMENT_REASON = (
    "ABAQUS/Explicit offers no CPS4I; CPS4R with enhanced hourglass control is its element that bends "
    "without locking or hourglassing at one element through the thickness"
)
SUPPORTS = ("free", "propped")
#: ABAQUS/Explicit's default bulk viscosity (linear b1, quadratic b2), written out in every scene deck so the
#: deck states it; the quadratic term does not act on CPS4R (Abaqus Getting Started, "Bulk viscosity")
BULK_VISCOSITY = (0.06, 1.2)
#: ``*CONTACT PAIR, MECHANICAL CONSTRAINT=`` per project contact method (the documented values are
#: KINEMATIC, the default of contact pairs, and PENALTY; Abaqus Keywords Reference, *CONTACT PAIR)
MECHANICAL_CONSTRAINT = {"kinematic": "KINEMATIC", "fixed_normal": "KINEMATIC", "penalty": "PENALTY"}
#: whole-model energies requested as history (ABAQUS/Explicit output variable identifiers)
ENERGY_VARIABLES = ("ALLKE", "ALLSE", "ALLIE", "ALLAE", "ALLVD", "ALLFD", "ALLWK", "ETOTAL")
#: contact history of the pair: total normal and shear force over the slave surface
CONTACT_TOTALS = ("CFN", "CFS")
#: contact history at node 1: pressure and shear (CSTRESS), opening and slip (CDISP)
CONTACT_NODE_VARIABLES = ("CSTRESS", "CDISP")


def _num(x: float) -> str:
    """A number as ABAQUS reads it: 12 significant digits, always with a decimal point or exponent."""
    s = f"{float(x):.12g}"
    return s if any(c in s for c in ".eEn") else s + "."


def _id_lines(ids, per_line: int = 16) -> list[str]:
    """1-based ids, at most 16 to a data line (ABAQUS's limit)."""
    ids = [int(i) for i in ids]
    return [", ".join(str(i) for i in ids[k : k + per_line]) for k in range(0, len(ids), per_line)]


def _nodes(coords, ids=None) -> list[str]:
    """``*NODE`` data lines: the id (default 1, 2, ...), then the coordinates."""
    ids = range(1, len(coords) + 1) if ids is None else ids
    return [", ".join([str(i), *map(_num, xyz)]) for i, xyz in zip(ids, coords)]


def _elements(rows, first: int = 1) -> list[str]:
    """``*ELEMENT`` data lines: the ids from ``first`` on, then each row's node ids."""
    return [", ".join(str(int(n)) for n in (e, *row)) for e, row in enumerate(rows, start=first)]


def _nset(name: str, ids) -> list[str]:
    return [f"*NSET, NSET={name}", *_id_lines(ids)]


def _material(beam: BeamParams, damping_beta: float = 0.0, name: str = "STEEL") -> list[str]:
    lines = [
        f"*MATERIAL, NAME={name}",
        "*ELASTIC",
        f"{_num(beam.E)}, {_num(beam.poisson_ratio)}",
        "*DENSITY",
        _num(beam.rho),
    ]
    if damping_beta > 0:
        lines += ["*DAMPING, BETA=" + _num(damping_beta)]
    return lines


# -------------------------------------------------------------------------------------------- linear decks
@dataclass(frozen=True)
class BrickStrip:
    """The continuum's nx x ny strip extruded one element through the width b (z from 0 to b).

    Node id (1-based) = 2-D node id + 1 on z = 0 and + 1 + n2 on z = b (n2 = nodes of the 2-D mesh)."""

    nodes: np.ndarray  #: (n, 3) coordinates [mm]
    elements: np.ndarray  #: (n_el, 8) 1-based node ids (face z = 0 counter-clockwise, then z = b)
    clamp: np.ndarray  #: 1-based ids on x = 0
    face_z0: np.ndarray  #: 1-based ids on z = 0
    tip_lower: np.ndarray  #: 1-based ids of the free-end lower corner (x = L, y = -h/2), both z
    tip_upper: np.ndarray  #: 1-based ids of the free-end upper corner (x = L, y = +h/2), both z


def brick_strip(beam: BeamParams, nx: int, ny: int) -> BrickStrip:
    m = strip_mesh(beam, nx, ny)
    n2 = m.n_nodes
    nodes = np.vstack(
        [np.column_stack([m.nodes, np.zeros(n2)]), np.column_stack([m.nodes, np.full(n2, beam.width)])]
    )
    q = m.quads + 1
    elements = np.hstack([q, q + n2])
    both = lambda ids: np.concatenate([np.asarray(ids) + 1, np.asarray(ids) + 1 + n2])  # noqa: E731
    return BrickStrip(
        nodes,
        elements,
        both(m.clamp),
        np.arange(1, n2 + 1),
        both([m.lower[-1]]),
        both([m.upper[-1]]),
    )


@checked_arguments(nx=Count, ny=Count, support=Literal[SUPPORTS], n_modes=Count)
def linear_deck(beam: BeamParams, nx: int, ny: int, support: str, n_modes: int = 10, title: str = "") -> str:
    """The strip as C3D8I bricks: step 1 the static self-weight state (corner displacements; the prop's
    reaction), step 2 the lowest ``n_modes`` natural frequencies with the free-end corners' displacements
    per mode (to tell in-plane bending from other modes). ``support``: ``free`` tip or ``propped`` (u_y = 0
    at the free-end lower corner: the contact held at angle 0)."""
    s = brick_strip(beam, nx, ny)
    out = [
        "*HEADING",
        (title or f"stickslip strip {beam.length:g} x {beam.thickness:g} x {beam.width:g} mm, {support} tip"),
        f"** element {LINEAR_ELEMENT}: {LINEAR_ELEMENT_REASON}",
        "** units: mm, s, N, t (tonne), MPa",
        "*NODE, NSET=NALL",
    ]
    out += [*_nodes(s.nodes), f"*ELEMENT, TYPE={LINEAR_ELEMENT}, ELSET=STRIP", *_elements(s.elements)]
    out += _nset("CLAMP", s.clamp) + _nset("ZFACE", s.face_z0)
    out += _nset("TIPLOW", s.tip_lower) + _nset("TIPUP", s.tip_upper) + _nset("PROP", s.tip_lower)
    out += _material(beam)
    out += ["*SOLID SECTION, ELSET=STRIP, MATERIAL=STEEL", "*BOUNDARY", "CLAMP, 1, 3", "ZFACE, 3, 3"]
    if support == "propped":
        out += ["PROP, 2, 2"]
    prints = ["*NODE PRINT, NSET=TIPLOW", "U", "*NODE PRINT, NSET=TIPUP", "U"]
    # the static step first: its tables then come before any mode's in the .dat file
    out += ["*STEP", "*STATIC", "*DLOAD", f"STRIP, GRAV, {_num(beam.g)}, 0., -1., 0.", *prints]
    if support == "propped":
        out += ["*NODE PRINT, NSET=PROP, TOTALS=ONLY", "RF"]
    out += ["*END STEP", "*STEP", "*FREQUENCY", str(n_modes), *prints, "*END STEP"]
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------------------------- scene decks
def friction_data_lines(friction: FrictionTable) -> list[str]:
    """``*FRICTION`` data lines of a mu(slip rate) table: ``mu, slip rate`` per row (ABAQUS reads the first
    row's mu as the static value; slip rate in the model's units, mm s-1)."""
    return [f"{_num(m)}, {_num(v)}" for v, m in zip(friction.speeds, friction.mu)]


def disc_geometry(beam: BeamParams, disc: DiscParams, contact: ContactParams) -> tuple[tuple, float, float]:
    """(centre (x, y) [mm], radius [mm], angular velocity about +z [rad s-1]) of the disc touching the
    free-end lower corner with its outward normal tilted by ``contact.angle_deg`` towards the clamp (as
    ``fe.continuum.build_continuum``); clockwise (the paper's) is a negative rotation about +z."""
    r = disc.diameter / 2.0
    a = math.radians(contact.angle_deg)
    cx = beam.length + r * math.sin(a)
    cy = -beam.thickness / 2.0 - r * math.cos(a)
    sign = -1.0 if disc.direction == "clockwise" else 1.0
    return (cx, cy), r, sign * disc.surface_speed / r


def _disc_arcs(centre, r: float, start_angle: float, n_arcs: int = 4) -> list[str]:
    """A full circle as ``n_arcs`` CIRCL segments (each < 180 deg), traversed clockwise from
    ``start_angle`` so that the outward normal (left of the path in ABAQUS's 2-D segment convention) points
    away from the centre."""
    cx, cy = centre
    pts = [start_angle - 2 * math.pi * k / n_arcs for k in range(n_arcs + 1)]
    lines = [f"START, {_num(cx + r * math.cos(pts[0]))}, {_num(cy + r * math.sin(pts[0]))}"]
    for ang in pts[1:]:
        lines.append(
            f"CIRCL, {_num(cx + r * math.cos(ang))}, {_num(cy + r * math.sin(ang))}, {_num(cx)}, {_num(cy)}"
        )
    return lines


def _damping_lines(beta: float) -> list[str]:
    if beta <= 0:
        return ["DAMPING: none added (stiffness_damping 0)."]
    return [
        f"DAMPING: *DAMPING, BETA = {beta:g} s (stiffness proportional), added on purpose: beta*omega/2",
        "  = 2e-4 at the first axial mode (12.9 kHz) at beta 5e-9 s, 6e-6 at the propped bending mode",
        "  (365 Hz), 6e-3 at 400 kHz (mesh modes); it keeps the falling friction law from driving mesh",
        "  modes as fast as the physical ones (config/fe.yaml, fe.defaults.solver).",
    ]


def scene_header(name, beam, disc, contact, solver, friction, nx, ny, constant_mu) -> list[str]:
    """The ``**`` comment block of a scene deck: every modelling choice the deck makes, with its reason."""
    a, b = BULK_VISCOSITY
    method = MECHANICAL_CONSTRAINT[contact.method]
    lines = [
        "Written by stickslip.fe.abaqus_deck.scene_deck for ABAQUS/Explicit (the paper ran 6.6-3).",
        "UNITS: mm, s, N, t (tonne), MPa; density t mm-3, gravity 9810 mm s-2, slip rate mm s-1.",
        f"MESH: {nx} x {ny} {SCENE_ELEMENT}, plane stress, thickness (out of plane) {beam.width:g} mm;",
        f"  {SCENE_ELEMENT_REASON}.",
        "MASS: ABAQUS/Explicit's lumped mass (the only one it has).",
        "NLGEOM=YES: ABAQUS/Explicit's default, written out; displacements are micrometres, so the",
        "  geometric nonlinearity is negligible (the project's models are small-displacement).",
        f"BULK VISCOSITY: ABAQUS/Explicit's defaults written out, linear b1 = {a:g}, quadratic b2 = {b:g}",
        "  (the quadratic term does not act on CPS4R; b1 damps the highest element frequency by 6 %).",
        *_damping_lines(solver.stiffness_damping),
        f"CONTACT: *CONTACT PAIR, MECHANICAL CONSTRAINT={method} ({contact.method}), node-to-surface",
        "  (the default of a pair with an analytical rigid master), finite sliding, slave = the strip's",
        "  lower face (the paper's slave surface), master = the analytical rigid disc DISC turned about",
        f"  its reference node at {disc.surface_speed:.6g} mm/s surface speed ({disc.direction}), contact",
        f"  angle {contact.angle_deg:g} deg at the free-end lower corner.",
    ]
    if contact.method == "penalty":
        lines += [
            f"  Penalty: linear pressure-overclosure from the project's {contact.penalty_stiffness:g} N/mm",
            "  at the contact node divided by the node's face area (see *SURFACE BEHAVIOR).",
        ]
    if contact.method == "fixed_normal":
        lines += ["  Section 10: the upper face held vertically (u_2 = 0), set UPPER."]
    if constant_mu is None:
        lines += [
            f"FRICTION: *FRICTION mu(slip rate), {len(friction.mu)} rows (mu, slip rate [mm/s]) from the",
            "  project's Fig. 17 table (results/onedof/friction_mu_vr.csv, rule friction_table: the 1-DOF",
            f"  model's mu vs relative velocity); mu({_num(friction.speeds[0])}) = {friction.mu[0]:g} is",
            "  ABAQUS's static value, linear between rows, constant beyond the last (as the project's law).",
        ]
    else:
        lines += [f"FRICTION: one constant mu = {constant_mu:g} (not the Fig. 17 table)."]
    lines += [
        "START: undeformed, at rest, gravity from t = 0 (the drop start of ABAQUS/Explicit)"
        + ("" if solver.initial_state != "static" else "; the scene's static start needs a prior step")
        + ".",
        f"OUTPUT: history every {solver.output_dt:g} s: node 1 (set NODE1, {contact.output_node}) U1 U2",
        f"  V1 V2; the pair's {' '.join(CONTACT_TOTALS)} (total normal and shear contact force); node 1's",
        f"  {' '.join(CONTACT_NODE_VARIABLES)} (pressure, shear, opening, slip: its stick/slip/open state);",
        f"  energies {' '.join(ENERGY_VARIABLES)}; CSTATUS of node 1 as field output (a field variable).",
    ]
    return ["** " + line for line in lines]


def scene_deck(
    name: str,
    mapping: Mapping,
    friction: FrictionTable,
    nx: int,
    ny: int,
    *,
    constant_mu: float | None = None,
) -> str:
    """ABAQUS/Explicit deck of one Section 9-12 scene (merged scene mapping,
    ``studies.fe_config.scene_mapping``) on the continuum's nx x ny mesh. ``constant_mu``: write one
    friction coefficient instead of the table (for codes without mu(slip rate))."""
    p = SceneParams.from_mapping(mapping)
    beam, disc, contact, solver = p.beam, p.disc, p.contact, p.solver
    m = strip_mesh(beam, nx, ny)
    centre, r, omega = disc_geometry(beam, disc, contact)
    ref = m.n_nodes + 1
    node1 = {"free_end_lower": [m.lower[-1]], "free_end_upper": [m.upper[-1]]}.get(
        contact.output_node, [m.lower[-1], m.upper[-1]]
    )
    held = contact.method == "fixed_normal"
    method = MECHANICAL_CONSTRAINT[contact.method]
    a = math.radians(contact.angle_deg)
    out = [
        "*HEADING",
        f"stickslip scene {name}: steel strip {beam.length:g} x {beam.thickness:g} mm "
        f"(width {beam.width:g} mm) "
        f"on a rigid disc D {disc.diameter:g} mm, {contact.method} contact at {contact.angle_deg:g} deg, "
        f"surface speed {disc.surface_speed:.6g} mm/s {disc.direction}",
        *scene_header(name, beam, disc, contact, solver, friction, nx, ny, constant_mu),
        "*NODE, NSET=BEAM",
    ]
    out += [*_nodes(m.nodes), "*NODE, NSET=DISCREF", *_nodes([centre], [ref])]
    out += [f"*ELEMENT, TYPE={SCENE_ELEMENT}, ELSET=STRIP", *_elements(m.quads + 1)]
    out += _nset("CLAMP", m.clamp + 1) + _nset("NODE1", np.asarray(node1) + 1)
    if held:
        out += _nset("UPPER", m.upper + 1)
    lower_el = np.arange(nx) + 1  # the first row of elements: face S1 (nodes 1-2) is the lower face
    out += [
        "*ELSET, ELSET=LOWER_EL",
        *_id_lines(lower_el),
        "*SURFACE, TYPE=ELEMENT, NAME=LOWER",
        "LOWER_EL, S1",
    ]
    out += ["*SURFACE, TYPE=SEGMENTS, NAME=DISC"] + _disc_arcs(
        centre, r, math.pi / 2 + a
    )  # from the contact point
    out += ["*RIGID BODY, REF NODE=DISCREF, ANALYTICAL SURFACE=DISC"]
    out += _material(beam, solver.stiffness_damping)
    out += [
        "*SOLID SECTION, ELSET=STRIP, MATERIAL=STEEL, CONTROLS=HG",
        _num(beam.width),
        "*SECTION CONTROLS, NAME=HG, HOURGLASS=ENHANCED",
        "*SURFACE INTERACTION, NAME=FIG18",
        "*FRICTION",
    ]
    out += [_num(constant_mu)] if constant_mu is not None else friction_data_lines(friction)
    if contact.method == "penalty":
        # the project's penalty is a force per penetration at the contact node [N mm-1]; ABAQUS's linear
        # pressure-overclosure wants pressure per overclosure [MPa mm-1]: divided by the node's face area
        area = beam.width * beam.length / nx / 2.0
        out += [
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
            f"** {contact.penalty_stiffness:g} N/mm at the corner node over its face area {area:g} mm2",
            _num(contact.penalty_stiffness / area),
        ]
    out += ["*BOUNDARY", "CLAMP, 1, 2", "DISCREF, 1, 2"]
    if held:
        out += ["UPPER, 2, 2"]
    interval = _num(solver.output_dt)
    out += [
        "*STEP, NLGEOM=YES",
        "*DYNAMIC, EXPLICIT",
        f", {_num(solver.t_end)}",
        "*BULK VISCOSITY",
        ", ".join(_num(b) for b in BULK_VISCOSITY),
        "*BOUNDARY, TYPE=VELOCITY",
        f"DISCREF, 6, 6, {_num(omega)}",
        "*DLOAD",
        f"STRIP, GRAV, {_num(beam.g)}, 0., -1.",
        f"*CONTACT PAIR, INTERACTION=FIG18, MECHANICAL CONSTRAINT={method}",
        "LOWER, DISC",
        f"*OUTPUT, HISTORY, TIME INTERVAL={interval}",
        "*NODE OUTPUT, NSET=NODE1",
        "U1, U2, V1, V2",
        "*CONTACT OUTPUT, SLAVE=LOWER, MASTER=DISC",
        ", ".join(CONTACT_TOTALS),
        "*CONTACT OUTPUT, SLAVE=LOWER, MASTER=DISC, NSET=NODE1",
        ", ".join(CONTACT_NODE_VARIABLES),
        "*ENERGY OUTPUT",
        ", ".join(ENERGY_VARIABLES),
        f"*OUTPUT, FIELD, TIME INTERVAL={interval}",
        "*CONTACT OUTPUT, SLAVE=LOWER, MASTER=DISC, NSET=NODE1",
        "CSTATUS",
        "*END STEP",
    ]
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------------------------------------- parsing
@dataclass(frozen=True)
class Deck:
    """What ``read_deck`` finds in a deck."""

    keywords: tuple  #: every keyword line's keyword, upper case, in order (``*NODE``, ...)
    nodes: dict  #: node id -> coordinates
    elements: dict  #: element type -> {element id: node ids}
    friction: tuple  #: rows of the ``*FRICTION`` data lines, as floats
    blocks: tuple  #: (keyword line, data lines) in order


_KEYWORD = re.compile(r"^\*(?!\*)\s*([^,]+)")


def read_deck(text: str) -> Deck:
    """Parse an ABAQUS-style deck: keyword lines, their data lines (comments ``**`` skipped)."""
    blocks: list[tuple[str, list[str]]] = []
    for raw in text.splitlines():
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            blocks.append((line, []))
        elif blocks:
            blocks[-1][1].append(line)
        else:
            raise ValueError(f"deck: data line before any keyword: {line!r}")
    keywords, nodes, elements, friction = [], {}, {}, []
    for head, data in blocks:
        kw = _KEYWORD.match(head).group(1).strip().upper()
        keywords.append(f"*{kw}")
        params = _params(head)
        rows = [[f.strip() for f in d.split(",") if f.strip()] for d in data]
        if kw == "NODE":
            for r in rows:
                nodes[int(r[0])] = tuple(float(v) for v in r[1:])
        elif kw == "ELEMENT":
            el = elements.setdefault(params.get("TYPE", "?"), {})
            for r in rows:
                el[int(r[0])] = tuple(int(v) for v in r[1:])
        elif kw == "FRICTION":
            friction += [tuple(float(v) for v in r) for r in rows]
    return Deck(tuple(keywords), nodes, elements, tuple(friction), tuple((h, tuple(d)) for h, d in blocks))


def _params(head: str) -> dict:
    out = {}
    for part in head.split(",")[1:]:
        k, _, v = part.partition("=")
        out[k.strip().upper()] = v.strip()
    return out


def friction_table_of(deck: Deck) -> FrictionTable:
    """The mu(slip rate) table of a deck's ``*FRICTION`` rows (``mu, slip rate``)."""
    if not deck.friction:
        raise ValueError("deck: no *FRICTION data")
    if len(deck.friction[0]) < 2:
        return FrictionTable((0.0,), (deck.friction[0][0],))
    return FrictionTable(tuple(r[1] for r in deck.friction), tuple(r[0] for r in deck.friction))
