"""Rigid rotating disc geometry and the contact/output vectors of the contact point ("node 1").

Small-displacement kinematics (displacements are micrometres against a 12.5 mm disc radius): the
contact normal n and tangent t are fixed at their initial directions and the gap is linear in the DOFs,
g = g0 + c_n . q. The disc surface moves along t with its surface speed V; the rigid surface itself does
not move, so rotation enters only through V.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .beam import BeamModel
from .params import ContactParams


@dataclass(frozen=True)
class ContactGeometry:
    c_x: np.ndarray  #: q -> horizontal displacement of the output point ("node 1") [mm/mm]
    c_y: np.ndarray  #: q -> vertical displacement of the output point
    c_n: np.ndarray  #: q -> normal displacement (gap increment, + = opening)
    c_t: np.ndarray  #: q -> tangential displacement along the disc surface velocity
    normal: tuple  #: outward disc normal (nx, ny)
    tangent: tuple  #: disc surface velocity direction (tx, ty)
    disc_centre: tuple  #: disc centre (x, y) [mm], beam axis on y = 0, clamp at x = 0


#: offset of the output node below the beam axis, in units of h/2
_OUTPUT_OFFSET = {"free_end_lower": 1.0, "free_end_axis": 0.0, "free_end_upper": -1.0}


def contact_geometry(
    beam: BeamModel, contact: ContactParams, disc_radius: float, direction: str = "clockwise"
) -> ContactGeometry:
    """Contact and output vectors. A point (0, -d) below the free-end node moves by (u + theta d, v)
    under small rotations theta (counter-clockwise positive). The contact point is the lower corner
    (d = h/2) with ``surface_offset``, else the axis node; the output point ("node 1") is
    ``contact.output_node``. ``direction`` counterclockwise reverses the disc surface velocity."""
    p = beam.params
    off = p.thickness / 2.0 if contact.surface_offset else 0.0
    ex = beam.selector(beam.tip_dof(0))
    ey = beam.selector(beam.tip_dof(1))
    et = beam.selector(beam.tip_dof(2))
    k_x = ex + off * et  # contact point
    d_out = _OUTPUT_OFFSET[contact.output_node] * p.thickness / 2.0
    c_x = ex + d_out * et  # output point
    c_y = ey
    a = math.radians(contact.angle_deg)
    sgn = 1.0 if direction == "clockwise" else -1.0
    n = (-math.sin(a), math.cos(a))
    t = (sgn * math.cos(a), sgn * math.sin(a))
    c_n = n[0] * k_x + n[1] * ey
    c_t = t[0] * k_x + t[1] * ey
    corner = (p.length, -off)
    centre = (corner[0] - disc_radius * n[0], corner[1] - disc_radius * n[1])
    return ContactGeometry(c_x, c_y, c_n, c_t, n, t, centre)
