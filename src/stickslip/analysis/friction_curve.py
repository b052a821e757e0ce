"""Fig. 17: the friction coefficient versus relative velocity along a solution, as the FE scenes' table."""

from __future__ import annotations

import numpy as np

from ..model.friction import AffineFriction
from ..solvers.base import STICK


def friction_along_solution(v, vb, phase, law: AffineFriction, normal_force: float):
    """(|v_r|, |mu|) of every slip sample with v_r != 0: the friction the law gives there, divided by N."""
    v, vb, phase = np.asarray(v), np.asarray(vb), np.asarray(phase)
    # at v_r = 0 exactly (a switching sample) friction is set-valued: sgn(0) = 0 would report mu = 0 there
    slip = (phase != STICK) & np.isfinite(v) & (v != vb)
    speed = np.abs(v[slip] - vb[slip])
    mu = np.abs(law.force(v[slip], vb[slip])) / normal_force
    return speed, mu


def friction_table(speed, mu, mu_static: float, bins: int):
    """Tabulated mu(|v_r|) for an explicit FE contact law: mu_static at rest, then bin means, ascending.

    ABAQUS-style tables interpolate linearly and hold the last value beyond the end; so does ``np.interp``.
    """
    if bins < 2:
        raise ValueError(f"bins: need at least 2, got {bins}")
    if len(speed) == 0:
        return np.array([0.0]), np.array([mu_static])
    edges = np.linspace(0.0, float(np.max(speed)), bins + 1)
    index = np.clip(np.digitize(speed, edges) - 1, 0, bins - 1)
    centres, means = [], []
    for k in range(bins):
        sel = index == k
        if sel.any():
            centres.append(float(np.mean(speed[sel])))
            means.append(float(np.mean(mu[sel])))
    return np.concatenate(([0.0], centres)), np.concatenate(([mu_static], means))
