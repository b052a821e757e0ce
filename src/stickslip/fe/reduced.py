"""Reduced (modal) model: Craig-Bampton with the contact node's DOFs kept physical.

q = T [eta; q_b]: ``n_modes`` fixed-interface beam modes (contact node held) plus one static constraint mode
per contact-node DOF. The contact vectors act only on q_b, so the same explicit contact algorithm runs on
the reduced system unchanged; its stable step follows from its own (much lower) highest frequency.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from .explicit import System


def craig_bampton(
    system: System,
    boundary: np.ndarray,
    n_modes: int,
    axial_mask: np.ndarray | None = None,
    n_axial_modes: int = 0,
) -> tuple[System, np.ndarray]:
    """Return (reduced System, transformation T with q = T r).

    ``n_modes`` lowest fixed-interface modes; with ``axial_mask`` (True on axial DOFs) the modes are split
    into families and the ``n_modes`` lowest bending plus ``n_axial_modes`` lowest axial modes are kept:
    the stick-slip dynamics live in the first axial mode (12.9 kHz), far above tens of bending modes.
    """
    if n_modes < 0 or n_axial_modes < 0:
        raise ValueError(f"n_modes: mode counts must be >= 0, got {n_modes} and {n_axial_modes} axial")
    n = system.n
    b = np.asarray(sorted(set(int(i) for i in boundary)))
    i = np.setdiff1d(np.arange(n), b)
    K, M = system.K, system.M
    Kii, Kib = K[np.ix_(i, i)], K[np.ix_(i, b)]
    Mii = M[np.ix_(i, i)]
    psi = -np.linalg.solve(Kii, Kib)
    _, phi_all = sla.eigh(Kii, Mii)
    if axial_mask is None:
        pick = np.arange(min(n_modes, i.size))
    else:
        am = np.asarray(axial_mask, bool)[i]
        axial = (phi_all[am] ** 2).sum(axis=0) > 0.5 * (phi_all**2).sum(axis=0)
        pick = np.sort(
            np.concatenate([np.nonzero(~axial)[0][:n_modes], np.nonzero(axial)[0][:n_axial_modes]])
        )
    phi = phi_all[:, pick]
    k = phi.shape[1]
    T = np.zeros((n, k + b.size))
    T[np.ix_(i, np.arange(k))] = phi
    T[np.ix_(i, k + np.arange(b.size))] = psi
    T[b, k + np.arange(b.size)] = 1.0
    red = System(
        T.T @ M @ T,
        T.T @ K @ T,
        T.T @ system.f,
        T.T @ system.c_x,
        T.T @ system.c_y,
        T.T @ system.c_n,
        T.T @ system.c_t,
        label=f"craig_bampton_{k}modes+{b.size}dofs",
    )
    return red, T


def contact_boundary(system: System) -> np.ndarray:
    """Indices of the DOFs the contact/output vectors touch."""
    used = np.abs(system.c_x) + np.abs(system.c_y) + np.abs(system.c_n) + np.abs(system.c_t)
    return np.nonzero(used)[0]
