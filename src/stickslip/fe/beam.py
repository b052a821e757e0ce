"""2-D frame (beam-column) elements: axial bar + Rayleigh bending (Euler-Bernoulli stiffness, rotary inertia
of the cross-sections switchable), 3 DOF per node (u, v, theta).

Small pure functions in the scikit-fem spirit: element matrices are built batched for all elements, then
scattered into global matrices with one sparse COO assembly (no Python loop over elements).
Global DOF numbering: node i -> (3i, 3i+1, 3i+2) = (u_i, v_i, theta_i); node 0 is the clamped end.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp

from .params import BeamParams

#: closed-form beta_n L of a clamped-free Euler-Bernoulli beam
CANTILEVER_BETA_L = (1.8751040687, 4.6940911330, 7.8547574382, 10.9955407349, 14.1371683910)


#: the bending DOFs of a frame element (v1, t1, v2, t2) and the power of l in each bending-block entry:
#: entries coupling theta carry l (one theta) or l^2 (two thetas)
BENDING_DOFS = [1, 2, 4, 5]
LENGTH_POWERS = np.array([[0, 1, 0, 1], [1, 2, 1, 2], [0, 1, 0, 1], [1, 2, 1, 2]])


def node_coordinates(length: float, n_elements: int) -> np.ndarray:
    return np.linspace(0.0, length, n_elements + 1)


def element_stiffness(EA: float, EI: float, le: np.ndarray) -> np.ndarray:
    """(n_el, 6, 6) frame element stiffness, DOF order (u1, v1, t1, u2, v2, t2)."""
    le = np.asarray(le, float)
    k = np.zeros((le.size, 6, 6))
    a = EA / le
    k[:, 0, 0] = k[:, 3, 3] = a
    k[:, 0, 3] = k[:, 3, 0] = -a
    b = EI / le**3
    kb = np.array([[12, 6, -12, 6], [6, 4, -6, 2], [-12, -6, 12, -6], [6, 2, -6, 4]], float)
    for i, gi in enumerate(BENDING_DOFS):
        for j, gj in enumerate(BENDING_DOFS):
            k[:, gi, gj] = b * kb[i, j] * le ** LENGTH_POWERS[i, j]
    return k


def element_mass(rhoA: float, le: np.ndarray, kind: str = "lumped", rhoI: float = 0.0) -> np.ndarray:
    """(n_el, 6, 6) element mass. ``consistent``: cubic Hermite + linear axial; ``lumped``: HRZ
    diagonal (translations m/2, rotations m l^2/78), the usual choice of explicit codes.

    ``rhoI`` [t mm]: rotary inertia of the cross-sections (Rayleigh beam). Consistent: the Hermite
    rotary-inertia matrix rho I/(30 l) [36, 3l, -36, 3l; ...]; lumped: each node gets the rotary inertia of
    its half element, rho I l/2. Without it the HRZ rotational mass m l^2/78 vanishes as l^3 under
    refinement, and so does the tangential inertia of a point on the beam face (offset h/2)."""
    le = np.asarray(le, float)
    m = rhoA * le
    out = np.zeros((le.size, 6, 6))
    if kind == "lumped":
        for d in (0, 1, 3, 4):
            out[:, d, d] = m / 2.0
        out[:, 2, 2] = out[:, 5, 5] = m * le**2 / 78.0 + rhoI * le / 2.0
        return out
    if kind != "consistent":
        raise ValueError(f"mass: must be 'lumped' or 'consistent', got {kind!r}")
    out[:, 0, 0] = out[:, 3, 3] = m / 3.0
    out[:, 0, 3] = out[:, 3, 0] = m / 6.0
    mb = np.array([[156, 22, 54, -13], [22, 4, 13, -3], [54, 13, 156, -22], [-13, -3, -22, 4]], float)
    mr = np.array([[36, 3, -36, 3], [3, 4, -3, -1], [-36, -3, 36, -3], [3, -1, -3, 4]], float)
    for i, gi in enumerate(BENDING_DOFS):
        for j, gj in enumerate(BENDING_DOFS):
            lp = le ** LENGTH_POWERS[i, j]
            out[:, gi, gj] = m / 420.0 * mb[i, j] * lp + rhoI / (30.0 * le) * mr[i, j] * lp
    return out


def element_gravity(q: float, le: np.ndarray) -> np.ndarray:
    """(n_el, 6) consistent nodal loads of a uniform transverse load q [N mm-1] (negative = downward)."""
    le = np.asarray(le, float)
    f = np.zeros((le.size, 6))
    f[:, 1] = f[:, 4] = q * le / 2.0
    f[:, 2] = q * le**2 / 12.0
    f[:, 5] = -q * le**2 / 12.0
    return f


def element_dofs(n_elements: int) -> np.ndarray:
    e = np.arange(n_elements)[:, None]
    return np.hstack([3 * e + np.arange(3), 3 * (e + 1) + np.arange(3)])


def assemble_matrix(ke: np.ndarray, dofs: np.ndarray, n_dof: int) -> sp.csr_matrix:
    rows = np.repeat(dofs, 6, axis=1).ravel()
    cols = np.tile(dofs, (1, 6)).ravel()
    return sp.coo_matrix((ke.ravel(), (rows, cols)), shape=(n_dof, n_dof)).tocsr()


def assemble_vector(fe: np.ndarray, dofs: np.ndarray, n_dof: int) -> np.ndarray:
    f = np.zeros(n_dof)
    np.add.at(f, dofs.ravel(), fe.ravel())
    return f


@dataclass(frozen=True)
class BeamModel:
    """Assembled beam restricted to the free DOFs (after the clamp and any extra constraint)."""

    K: np.ndarray  #: stiffness [N mm-1] (dense, free DOFs)
    M: np.ndarray  #: mass [t]
    f: np.ndarray  #: gravity load [N]
    free: np.ndarray  #: global indices of the free DOFs
    n_nodes: int
    params: BeamParams

    def selector(self, global_dof: int) -> np.ndarray:
        """Vector e with e @ q = q[global_dof] (zero if the DOF is constrained)."""
        e = np.zeros(self.free.size)
        hit = np.nonzero(self.free == global_dof)[0]
        if hit.size:
            e[hit[0]] = 1.0
        return e

    def tip_dof(self, component: int) -> int:
        return 3 * (self.n_nodes - 1) + component


def assemble_beam(p: BeamParams, constrain_transverse: bool = False) -> BeamModel:
    """Clamp node 0 (all 3 DOFs). ``constrain_transverse`` also fixes v and theta of every node (Section 10:
    the upper surface is held vertically, so an Euler-Bernoulli beam keeps only its axial motion)."""
    n_el = p.n_elements
    n_nodes = n_el + 1
    n_dof = 3 * n_nodes
    le = np.diff(node_coordinates(p.length, n_el))
    dofs = element_dofs(n_el)
    K = assemble_matrix(element_stiffness(p.E * p.area, p.E * p.inertia, le), dofs, n_dof)
    rhoI = p.rho * p.inertia if p.rotary_inertia else 0.0
    M = assemble_matrix(element_mass(p.rho * p.area, le, p.mass, rhoI), dofs, n_dof)
    f = assemble_vector(element_gravity(-p.rho * p.area * p.g, le), dofs, n_dof)
    fixed = {0, 1, 2}
    if constrain_transverse:
        fixed |= {3 * i + c for i in range(n_nodes) for c in (1, 2)}
    free = np.array(sorted(set(range(n_dof)) - fixed))
    Kd = K.toarray()[np.ix_(free, free)]
    Md = M.toarray()[np.ix_(free, free)]
    return BeamModel(Kd, Md, f[free], free, n_nodes, p)


def modal_analysis(K: np.ndarray, M: np.ndarray, n_modes: int | None = None):
    """Undamped modes: returns (frequencies [Hz], mass-normalised mode shapes as columns)."""
    w2, phi = sla.eigh(K, M)
    w2 = np.clip(w2, 0.0, None)
    if n_modes is not None:
        w2, phi = w2[:n_modes], phi[:, :n_modes]
    return np.sqrt(w2) / (2 * np.pi), phi


def cantilever_bending_frequencies(p: BeamParams, n: int = 3) -> np.ndarray:
    """Closed-form clamped-free bending frequencies [Hz]: f = (beta L)^2/(2 pi L^2) sqrt(EI/(rho A))."""
    bl = np.asarray(CANTILEVER_BETA_L[:n])
    return bl**2 / (2 * np.pi * p.length**2) * np.sqrt(p.E * p.inertia / (p.rho * p.area))


def cantilever_axial_frequencies(p: BeamParams, n: int = 3) -> np.ndarray:
    """Closed-form clamped-free axial frequencies [Hz]: f = (2k-1) c / (4 L), c = sqrt(E/rho)."""
    k = np.arange(1, n + 1)
    return (2 * k - 1) * np.sqrt(p.E / p.rho) / (4 * p.length)


def classify_modes(phi: np.ndarray, free: np.ndarray) -> np.ndarray:
    """True where a mode is predominantly axial (u DOFs carry most of its mass-free amplitude)."""
    is_u = (free % 3) == 0
    return (phi[is_u] ** 2).sum(axis=0) > (phi[~is_u & ((free % 3) == 1)] ** 2).sum(axis=0)


def cantilever_errors(p: BeamParams) -> tuple[np.ndarray, float]:
    """Relative errors of the free beam's first three bending frequencies and its first axial frequency
    against the closed-form cantilever (the mesh part of the convergence study)."""
    b = assemble_beam(p)
    fr, phi = modal_analysis(b.K, b.M)
    ax = classify_modes(phi, b.free)
    bending = np.abs(fr[~ax][:3] / cantilever_bending_frequencies(p, 3) - 1)
    return bending, abs(fr[ax][0] / cantilever_axial_frequencies(p, 1)[0] - 1)
