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
    c_x: np.ndarray  #: q -> horizontal displacement of the contact point [mm/mm]
    c_y: np.ndarray  #: q -> vertical displacement of the contact point
    c_n: np.ndarray  #: q -> normal displacement (gap increment, + = opening)
    c_t: np.ndarray  #: q -> tangential displacement along the disc surface velocity
    normal: tuple  #: outward disc normal (nx, ny)
    tangent: tuple  #: disc surface velocity direction (tx, ty)
    disc_centre: tuple  #: disc centre (x, y) [mm], beam axis on y = 0, clamp at x = 0


def contact_geometry(beam: BeamModel, contact: ContactParams, disc_radius: float) -> ContactGeometry:
    p = beam.params
    off = p.thickness / 2.0 if contact.surface_offset else 0.0
    ex = beam.selector(beam.tip_dof(0))
    ey = beam.selector(beam.tip_dof(1))
    et = beam.selector(beam.tip_dof(2))
    # lower-face point (0, -h/2) relative to the node: small rotation theta moves it by (theta*h/2, 0)
    c_x = ex + off * et
    c_y = ey
    a = math.radians(contact.angle_deg)
    n = (-math.sin(a), math.cos(a))
    t = (math.cos(a), math.sin(a))
    c_n = n[0] * c_x + n[1] * c_y
    c_t = t[0] * c_x + t[1] * c_y
    corner = (p.length, -off)
    centre = (corner[0] - disc_radius * n[0], corner[1] - disc_radius * n[1])
    return ContactGeometry(c_x, c_y, c_n, c_t, n, t, centre)
