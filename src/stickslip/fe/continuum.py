"""2-D plane-stress continuum strip on the rigid rotating disc: the paper's own kind of model (Sections 9-12).

The paper's ABAQUS/Explicit model: a deformable 100 x 1 mm steel strip clamped at its left end, its lower
face the slave surface of a node-to-surface contact with a rigid 25 mm disc, friction mu(v_r) from the
Fig. 17 table, explicit central differences. Here:

* Mesh: nx x ny four-node quadrilaterals, x along the strip (clamp at x = 0), y across it with the strip
  axis on y = 0 (lower face y = -h/2, upper face y = +h/2), plane stress with out-of-plane width b.
  Node id = j (nx + 1) + i (i along x, j across); DOFs (2 id, 2 id + 1) = (u_x, u_y).
* Element: Q4 with incompatible (bubble) modes, Wilson's Q6 in Taylor's QM6 form (the incompatible-mode
  gradients are evaluated with the centre Jacobian and scaled by det J0 / det J, so the patch test holds on
  any shape), 2 x 2 Gauss, the four internal modes condensed statically: ABAQUS's CPS4I kind. Pure bending
  of rectangular elements is exact, so one element through the thickness does not lock.
* Mass: row-sum lumped (diagonal); the internal modes carry no mass. Gravity as the lumped nodal weights.
* Disc: rigid, centre placed so that its surface touches the lower face at ``contact_position`` (default
  the free-end lower corner, as ``contact.py``) with the outward normal tilted by ``angle_deg`` from the
  vertical towards the clamp. Surface velocity V t with t = (n_y, -n_x) for clockwise rotation.
* Contact: every lower-face node whose initial gap is below ``candidate_gap`` is a slave node with its own
  fixed normal (small displacements); ``kinematic`` = exact non-penetration and exact stick by a
  predictor-corrector impulse, ``penalty`` = k_p * penetration. The "primary" node is the one touching at
  t = 0; its state and slip velocity are reported.
* Time integration: central differences with the half-step start, optional stiffness-proportional damping
  beta, the compiled loop of ``engine`` (element-by-element structure, node-wise contact);
  dt = safety_factor * dt_crit with dt_crit = (2 / omega_max) (sqrt(1 + xi^2) - xi), xi = beta omega_max / 2.

Units as ``params``: mm, s, N, t (tonne), MPa.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..model.params import Count, NonNegative, Positive, checked_arguments
from . import engine
from .driver import SEPARATED, STICK, ExplicitResult, critical_step, drive, pack_result, schedule
from .params import (
    DEFAULT_INITIAL_STATE,
    DEFAULT_SAFETY_FACTOR,
    BeamParams,
    ContactParams,
    DiscParams,
    FrictionTable,
    run_settings,
)

OUTPUT_NODES = ("free_end_lower", "free_end_upper", "free_end_axis", "contact")
CONTINUUM_METHODS = ("kinematic", "penalty")
_GAUSS = np.array([-1.0, 1.0]) / math.sqrt(3.0)
_XI = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])  # natural coords of the 4 nodes


# --------------------------------------------------------------------------------------------- element
def plane_stress_matrix(E: float, nu: float) -> np.ndarray:
    """Plane-stress constitutive matrix D [MPa] (engineering shear strain)."""
    return E / (1.0 - nu * nu) * np.array([[1.0, nu, 0.0], [nu, 1.0, 0.0], [0.0, 0.0, (1.0 - nu) / 2.0]])


def _shape_gradients(xi: float, eta: float) -> np.ndarray:
    """(2, 4) derivatives of the bilinear shape functions w.r.t. (xi, eta)."""
    return 0.25 * np.array([_XI[:, 0] * (1 + eta * _XI[:, 1]), _XI[:, 1] * (1 + xi * _XI[:, 0])])


def _b_matrix(dndx: np.ndarray) -> np.ndarray:
    """(3, 2k) strain-displacement matrix from (2, k) x/y gradients, DOF order (u1, v1, u2, v2, ...)."""
    k = dndx.shape[1]
    B = np.zeros((3, 2 * k))
    B[0, 0::2] = dndx[0]
    B[1, 1::2] = dndx[1]
    B[2, 0::2] = dndx[1]
    B[2, 1::2] = dndx[0]
    return B


def quad_stiffness(xy: np.ndarray, D: np.ndarray, width: float, incompatible: bool = True) -> np.ndarray:
    """(8, 8) stiffness of one quadrilateral (nodes counter-clockwise, ``xy`` (4, 2) [mm]).

    ``incompatible=True``: QM6 (Wilson's modes 1 - xi^2, 1 - eta^2 per direction with Taylor's centre
    Jacobian, condensed statically); ``False``: plain bilinear Q4 (locks in bending), for comparison.
    """
    J0 = _shape_gradients(0.0, 0.0) @ xy
    J0inv, det0 = np.linalg.inv(J0), np.linalg.det(J0)
    K = np.zeros((12, 12))
    for xi in _GAUSS:
        for eta in _GAUSS:
            J = _shape_gradients(xi, eta) @ xy
            detJ = np.linalg.det(J)
            if detJ <= 0:
                raise ValueError("mesh: element with non-positive Jacobian (nodes must be counter-clockwise)")
            dndx = np.linalg.solve(J, _shape_gradients(xi, eta))
            dp = J0inv @ np.array([[-2.0 * xi, 0.0], [0.0, -2.0 * eta]]) * (det0 / detJ)
            B = np.hstack([_b_matrix(dndx), _b_matrix(dp)])
            K += B.T @ D @ B * detJ * width
    if not incompatible:
        return K[:8, :8]
    return K[:8, :8] - K[:8, 8:] @ np.linalg.solve(K[8:, 8:], K[8:, :8])


def quad_lumped_mass(xy: np.ndarray, rho: float, width: float) -> np.ndarray:
    """(4,) row-sum lumped nodal masses [t] of one quadrilateral: m_i = rho b int N_i dA."""
    m = np.zeros(4)
    for xi in _GAUSS:
        for eta in _GAUSS:
            n = 0.25 * (1 + xi * _XI[:, 0]) * (1 + eta * _XI[:, 1])
            m += n * rho * width * np.linalg.det(_shape_gradients(xi, eta) @ xy)
    return m


# ------------------------------------------------------------------------------------------------ mesh
@dataclass(frozen=True)
class StripMesh:
    """Structured nx x ny quad mesh of the strip [0, L] x [-h/2, h/2]."""

    nodes: np.ndarray  #: (n_nodes, 2) coordinates [mm]; node id = j (nx + 1) + i
    quads: np.ndarray  #: (n_el, 4) node ids, counter-clockwise
    lower: np.ndarray  #: lower-face node ids (y = -h/2), ordered by x
    upper: np.ndarray  #: upper-face node ids (y = +h/2), ordered by x
    clamp: np.ndarray  #: node ids on x = 0 (all DOFs fixed)
    nx: int
    ny: int

    @property
    def n_nodes(self) -> int:
        return self.nodes.shape[0]

    @property
    def n_dof(self) -> int:
        return 2 * self.n_nodes

    @property
    def dofs(self) -> np.ndarray:
        """(n_el, 8) DOFs of each element: (u_x, u_y) of its four nodes in order."""
        return np.repeat(2 * self.quads, 2, axis=1) + np.tile([0, 1], 4)


@checked_arguments(nx=Count, ny=Count)
def strip_mesh(beam: BeamParams, nx: int, ny: int) -> StripMesh:
    x = np.linspace(0.0, beam.length, nx + 1)
    y = np.linspace(-beam.thickness / 2.0, beam.thickness / 2.0, ny + 1)
    X, Y = np.meshgrid(x, y)  # (ny+1, nx+1): row j, column i
    nodes = np.column_stack([X.ravel(), Y.ravel()])
    i, j = np.meshgrid(np.arange(nx), np.arange(ny))
    n0 = (j * (nx + 1) + i).ravel()
    quads = np.column_stack([n0, n0 + 1, n0 + nx + 2, n0 + nx + 1])
    ids = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    return StripMesh(nodes, quads, ids[0].copy(), ids[-1].copy(), ids[:, 0].copy(), int(nx), int(ny))


def assemble_strip(mesh: StripMesh, beam: BeamParams, incompatible: bool = True):
    """(K csr [N mm-1], lumped mass per DOF [t], gravity load [N], element stiffnesses (n_el, 8, 8),
    element nodal masses (n_el, 4)) over all DOFs (constraints not applied)."""
    D = plane_stress_matrix(beam.E, beam.poisson_ratio)
    xy = mesh.nodes[mesh.quads]  # (n_el, 4, 2)
    # structured meshes repeat one element shape: compute each distinct shape once
    shape_key = np.round(xy - xy[:, :1, :], 12).reshape(len(xy), -1)
    uniq, inv = np.unique(shape_key, axis=0, return_inverse=True)
    inv = np.asarray(inv).ravel()
    first = np.array([np.nonzero(inv == k)[0][0] for k in range(len(uniq))])
    ke_u = np.array([quad_stiffness(xy[e], D, beam.width, incompatible) for e in first])
    me_u = np.array([quad_lumped_mass(xy[e], beam.rho, beam.width) for e in first])
    ke, me = ke_u[inv], me_u[inv]
    dofs = mesh.dofs
    rows = np.repeat(dofs, 8, axis=1).ravel()
    cols = np.tile(dofs, (1, 8)).ravel()
    K = sp.coo_matrix((ke.ravel(), (rows, cols)), shape=(mesh.n_dof, mesh.n_dof)).tocsr()
    K.sum_duplicates()
    m_node = np.zeros(mesh.n_nodes)
    np.add.at(m_node, mesh.quads.ravel(), me.ravel())
    mass = np.repeat(m_node, 2)
    f = np.zeros(mesh.n_dof)
    f[1::2] = -m_node * beam.g
    return K, mass, f, ke, me


# ----------------------------------------------------------------------------------------------- scene
@dataclass(frozen=True)
class ContinuumScene:
    """Assembled strip, rigid disc and contact law, ready for ``integrate_continuum``."""

    beam: BeamParams
    disc: DiscParams
    contact: ContactParams
    friction: FrictionTable
    mesh: StripMesh
    K: sp.csr_matrix  #: stiffness over all DOFs [N mm-1]
    mass: np.ndarray  #: lumped mass per DOF [t]
    f: np.ndarray  #: gravity load [N]
    fixed: np.ndarray  #: boolean mask of constrained DOFs
    element_stiffness: np.ndarray  #: (n_el, 8, 8)
    element_mass: np.ndarray  #: (n_el, 4)
    contact_nodes: np.ndarray  #: candidate slave node ids (lower face)
    normals: np.ndarray  #: (n_c, 2) outward disc normals at the candidates
    tangents: np.ndarray  #: (n_c, 2) disc surface-velocity directions
    gap0: np.ndarray  #: (n_c,) initial gaps [mm]
    primary: int  #: index into contact_nodes of the node touching at t = 0
    disc_centre: tuple
    disc_speed: float  #: surface speed V [mm s-1] (>= 0; direction in ``tangents``)
    output_nodes: np.ndarray  #: node ids whose weighted mean is "node 1" (one node, or two about the axis)
    output_weights: np.ndarray  #: their weights
    output_name: str
    damping_beta: float  #: stiffness-proportional damping [s]

    @property
    def method(self) -> str:
        return self.contact.method

    @property
    def penalty_stiffness(self) -> float:
        return float(self.contact.penalty_stiffness) if self.method == "penalty" else 0.0

    @property
    def output_node(self) -> int:
        """Node id of "node 1" (-1 if it is the mean of two nodes)."""
        return int(self.output_nodes[0]) if self.output_nodes.size == 1 else -1

    @property
    def free(self) -> np.ndarray:
        return np.nonzero(~self.fixed)[0]


def _output_point(mesh: StripMesh, name, contact_node: int) -> tuple[np.ndarray, np.ndarray]:
    """(node ids, weights) of "node 1": one node, or the mean of the two free-end nodes straddling the axis
    (``free_end_axis`` with odd ny: the axis point of the linear free edge)."""
    free_end = np.arange(mesh.ny + 1) * (mesh.nx + 1) + mesh.nx
    one = np.ones(1)
    if isinstance(name, (int, np.integer)) and not isinstance(name, bool):
        if not 0 <= int(name) < mesh.n_nodes:
            raise ValueError(f"output_node: node id {name} outside 0..{mesh.n_nodes - 1}")
        return np.array([int(name)]), one
    if name == "free_end_lower":
        return free_end[:1].copy(), one
    if name == "free_end_upper":
        return free_end[-1:].copy(), one
    if name == "free_end_axis":
        if mesh.ny % 2 == 0:
            return free_end[mesh.ny // 2 : mesh.ny // 2 + 1].copy(), one
        return free_end[mesh.ny // 2 : mesh.ny // 2 + 2].copy(), np.array([0.5, 0.5])
    if name == "contact":
        return np.array([int(contact_node)]), one
    raise ValueError(f"output_node: must be a node id or one of {OUTPUT_NODES}, got {name!r}")


@checked_arguments(damping_beta=NonNegative, candidate_gap=Positive | None)
def build_continuum(
    beam: BeamParams,
    disc: DiscParams,
    contact: ContactParams,
    friction: FrictionTable,
    *,
    nx: int,
    ny: int,
    output_node: str | int = "free_end_lower",
    damping_beta: float = 0.0,
    contact_position: float | None = None,
    constrain_upper_face: bool = False,
    candidate_gap: float | None = None,
) -> ContinuumScene:
    """Assemble the strip and place the disc.

    ``contact_position``: x of the lower-face touching point [mm] (default L, the free-end lower corner); it
    snaps to the nearest lower-face node. The disc turns as ``disc.direction`` says (clockwise in the paper).
    ``constrain_upper_face``: hold u_y = 0 on the upper face (Section 10). ``candidate_gap``: lower-face
    nodes with an initial gap below it are slave nodes (default h). ``contact.surface_offset`` does not
    apply: the strip's contact is on its lower face by construction.
    """
    if contact.method not in CONTINUUM_METHODS:
        raise ValueError(f"method: the continuum strip supports {CONTINUUM_METHODS}, got {contact.method!r}")
    mesh = strip_mesh(beam, nx, ny)
    K, mass, f, ke, me = assemble_strip(mesh, beam)
    fixed = np.zeros(mesh.n_dof, bool)
    fixed[2 * mesh.clamp] = fixed[2 * mesh.clamp + 1] = True
    if constrain_upper_face:
        fixed[2 * mesh.upper + 1] = True

    xc = beam.length if contact_position is None else float(contact_position)
    if not (0.0 < xc <= beam.length):
        raise ValueError(f"contact_position: must lie in (0, L = {beam.length}], got {contact_position!r}")
    lx = mesh.nodes[mesh.lower, 0]
    k0 = int(np.argmin(np.abs(lx - xc)))
    if k0 == 0:
        raise ValueError("contact_position: snaps to the clamped node; move it away from x = 0")
    R = disc.diameter / 2.0
    a = math.radians(contact.angle_deg)
    n_touch = np.array([-math.sin(a), math.cos(a)])
    p_touch = mesh.nodes[mesh.lower[k0]]
    centre = p_touch - R * n_touch
    rel = mesh.nodes[mesh.lower] - centre
    dist = np.hypot(rel[:, 0], rel[:, 1])
    gaps = dist - R
    if np.any(gaps < -1e-9 * R):
        bad = float(lx[np.argmin(gaps)])
        raise ValueError(
            f"angle_deg: {contact.angle_deg:g} deg with the contact at x = {p_touch[0]:g} mm puts the disc "
            f"through the lower face at x = {bad:g} mm (a straight strip touches a disc only with the "
            "normal vertical, or tilted towards the clamp at the free-end corner)"
        )
    gmax = beam.thickness if candidate_gap is None else float(candidate_gap)
    cand = np.nonzero((gaps < gmax) & (np.arange(lx.size) > 0))[0]
    normals = rel[cand] / dist[cand, None]
    sgn = 1.0 if disc.direction == "clockwise" else -1.0
    tangents = sgn * np.column_stack([normals[:, 1], -normals[:, 0]])
    gap0 = np.maximum(gaps[cand], 0.0)
    gap0[cand == k0] = 0.0
    primary = int(np.nonzero(cand == k0)[0][0])
    contact_nodes = mesh.lower[cand]
    return ContinuumScene(
        beam, disc, contact, friction, mesh, K, mass, f, fixed, ke, me, contact_nodes, normals, tangents,
        gap0, primary, (float(centre[0]), float(centre[1])), float(disc.surface_speed),
        *_output_point(mesh, output_node, int(mesh.lower[k0])),
        output_node if isinstance(output_node, str) else f"node {output_node}", float(damping_beta),
    )  # fmt: skip


# ----------------------------------------------------------------------------------- stable time step
def omega_max_elementwise(scene: ContinuumScene) -> float:
    """Upper bound of omega_max [rad s-1]: the largest element eigenvalue of (K_e, M_e) with the element's
    share of the lumped mass (Irons' element-by-element theorem), plus k_p / m at the contact nodes."""
    me = np.repeat(scene.element_mass, 2, axis=1)  # (n_el, 8)
    s = 1.0 / np.sqrt(me)
    A = scene.element_stiffness * s[:, :, None] * s[:, None, :]
    w2 = float(np.linalg.eigvalsh(A)[:, -1].max())
    if scene.penalty_stiffness > 0:
        w2 += scene.penalty_stiffness / float(scene.mass[2 * scene.contact_nodes].min())
    return math.sqrt(w2)


def _penalty_matrix(scene: ContinuumScene) -> sp.csr_matrix:
    n = scene.mesh.n_dof
    if scene.penalty_stiffness <= 0:
        return sp.csr_matrix((n, n))
    d = np.column_stack([2 * scene.contact_nodes, 2 * scene.contact_nodes + 1])
    vals = scene.penalty_stiffness * np.einsum("ci,cj->cij", scene.normals, scene.normals)
    rows = np.repeat(d, 2, axis=1).ravel()
    cols = np.tile(d, (1, 2)).ravel()
    return sp.coo_matrix((vals.ravel(), (rows, cols)), shape=(n, n)).tocsr()


def omega_max_global(scene: ContinuumScene, tol: float = 1e-10) -> float:
    """omega_max [rad s-1] of the constrained assembled system (sparse Lanczos on M^-1/2 K M^-1/2, with all
    penalty springs closed)."""
    fr = scene.free
    s = sp.diags(1.0 / np.sqrt(scene.mass[fr]))
    A = (s @ (scene.K + _penalty_matrix(scene))[fr][:, fr] @ s).tocsr()
    start = np.random.default_rng(0).standard_normal(A.shape[0])  # fixed start: reruns give the same dt
    w2 = spla.eigsh(A, k=1, which="LA", tol=tol, v0=start, return_eigenvectors=False)[0]
    return float(math.sqrt(max(w2, 0.0)))


def stable_time_step(scene: ContinuumScene, method: str = "global") -> float:
    """dt_crit [s]. ``global``: from the assembled system's omega_max (the true limit, as ABAQUS/Explicit's
    global estimator approaches it); ``element``: from the element-by-element bound (conservative)."""
    if method == "element":
        w = omega_max_elementwise(scene)
    elif method == "global":
        w = omega_max_global(scene)
    else:
        raise ValueError(f"method: must be 'element' or 'global', got {method!r}")
    return critical_step(w, scene.damping_beta)


def increments(
    scene: ContinuumScene,
    duration: float,
    safety_factor: float = DEFAULT_SAFETY_FACTOR,
    method: str = "global",
) -> int:
    """Number of explicit increments to reach ``duration`` at safety_factor * dt_crit."""
    run_settings(duration, safety_factor)
    return schedule(duration, stable_time_step(scene, method), None, safety_factor, None)[1]


# ------------------------------------------------------------------------------------------ static state
def static_state(scene: ContinuumScene) -> tuple[np.ndarray, float]:
    """Gravity equilibrium with the primary contact node held on the disc (kinematic: gap exactly 0;
    penalty: spring). Returns (u over all DOFs, normal force [N]); free equilibrium if the disc would pull."""
    fr = scene.free
    nf = fr.size
    Kf = scene.K[fr][:, fr]
    ff = scene.f[fr]
    u = np.zeros(scene.mesh.n_dof)
    if scene.contact_nodes.size == 0:  # no slave node (contact-free checks)
        u[fr] = spla.spsolve(Kf.tocsc(), ff)
        return u, 0.0
    c = scene.contact_nodes[scene.primary]
    g = np.zeros(scene.mesh.n_dof)
    g[2 * c : 2 * c + 2] = scene.normals[scene.primary]
    gf = g[fr]
    if scene.method == "penalty":
        kp = scene.penalty_stiffness
        uf = spla.spsolve((Kf + kp * sp.csr_matrix(np.outer(gf, gf))).tocsc(), ff)
        N = -kp * float(gf @ uf)
    else:
        A = sp.bmat([[Kf, -sp.csr_matrix(gf[:, None])], [sp.csr_matrix(gf[None, :]), None]]).tocsc()
        sol = spla.spsolve(A, np.concatenate([ff, [0.0]]))
        uf, N = sol[:nf], float(sol[nf])
    if N <= 0:
        uf, N = spla.spsolve(Kf.tocsc(), ff), 0.0
    u[fr] = uf
    return u, N


# ------------------------------------------------------------------------------------------ modes
@checked_arguments(n_modes=Count)
def natural_frequencies(scene: ContinuumScene, n_modes: int = 10, contact_held: bool = True) -> np.ndarray:
    """Lowest ``n_modes`` natural frequencies [Hz] of the clamped strip (sparse shift-invert Lanczos);
    ``contact_held``: the primary contact node's normal displacement is held (bilateral contact, no friction),
    as in the linearisation about a closed contact."""
    n = scene.mesh.n_dof
    T = sp.identity(n, format="lil")
    keep = ~scene.fixed
    if contact_held and scene.contact_nodes.size:
        c = 2 * int(scene.contact_nodes[scene.primary])
        nrm = scene.normals[scene.primary]
        T[c : c + 2, c : c + 2] = np.array([[nrm[0], -nrm[1]], [nrm[1], nrm[0]]])  # columns n, n rotated 90
        keep = keep.copy()
        keep[c] = False  # the normal coordinate (equal nodal masses in x and y keep M diagonal)
    T = T.tocsr()[:, np.nonzero(keep)[0]]
    K = (T.T @ scene.K @ T).tocsc()
    M = (T.T @ sp.diags(scene.mass) @ T).tocsc()
    k = min(n_modes, K.shape[0] - 2)
    start = np.random.default_rng(0).standard_normal(K.shape[0])
    w2 = spla.eigsh(K, k=k, M=M, sigma=0.0, which="LM", v0=start, return_eigenvectors=False)
    return np.sqrt(np.clip(np.sort(w2), 0.0, None)) / (2 * np.pi)


# ------------------------------------------------------------------------------------------ integration
def quad_structure(scene: ContinuumScene, dt: float) -> engine.QuadStructure:
    """The engine's structure piece: the distinct element stiffnesses and each element's kind and DOFs,
    the lumped mass inverted (0 on constrained DOFs), gravity, stiffness-proportional damping."""
    quads = scene.mesh.quads
    dofs = scene.mesh.dofs.astype(np.int64)
    ke_flat = scene.element_stiffness.reshape(len(quads), -1)
    ke_types, kind = np.unique(ke_flat, axis=0, return_inverse=True)
    ke_types = np.ascontiguousarray(ke_types.reshape(-1, 8, 8))
    kind = np.asarray(kind, np.int64).ravel()
    minv = np.where(scene.fixed, 0.0, 1.0 / scene.mass)
    return engine.QuadStructure(
        dofs, kind, ke_types, minv, scene.f.copy(), float(scene.damping_beta), float(dt)
    )


def node_contact(scene: ContinuumScene, dt: float):
    """The engine's contact piece: every slave node with its normal, surface direction, gap and mass."""
    cdof = (2 * scene.contact_nodes).astype(np.int64)
    nodes = (
        cdof, np.ascontiguousarray(scene.normals), np.ascontiguousarray(scene.tangents), scene.gap0.copy(),
        scene.mass[cdof].copy(), float(scene.disc_speed), np.asarray(scene.friction.speeds, float),
        np.asarray(scene.friction.mu, float), int(scene.primary), float(dt),
    )  # fmt: skip
    return engine.SlaveNodes(*nodes, scene.penalty_stiffness)  # kinematic: 0


def node_recorder(scene: ContinuumScene, out: np.ndarray, ost: np.ndarray) -> engine.NodeRecorder:
    """The engine's recorder of "node 1" and the primary contact node's slip velocity."""
    onode = (2 * scene.output_nodes).astype(np.int64)
    ow = np.asarray(scene.output_weights, float)
    k = int(scene.primary)
    if 0 <= k < scene.contact_nodes.size:
        pdof, pt = 2 * int(scene.contact_nodes[k]), np.ascontiguousarray(scene.tangents[k], dtype=float)
    else:
        pdof, pt = -1, np.zeros(2)
    return engine.NodeRecorder(out, ost, onode, ow, pdof, pt, float(scene.disc_speed))


def integrate_continuum(
    scene: ContinuumScene,
    duration: float,
    *,
    safety_factor: float = DEFAULT_SAFETY_FACTOR,
    output_interval: float | None = None,
    initial_state: str = DEFAULT_INITIAL_STATE,
    progress=None,
    dt: float | None = None,
    u0: np.ndarray | None = None,
    v0: np.ndarray | None = None,
    record_state: bool = False,
    blowup: float = 1e3,
    chunk: int = 200_000,
) -> ExplicitResult:
    """Run ``duration`` seconds; returns the trajectory of the output node ("node 1") as ``ExplicitResult``.

    ``initial_state``: "drop" (= "undeformed": u = 0, v = 0, gravity on at t = 0, contact closed at the
    undeformed lower-face point) or "static" (gravity equilibrium in contact). ``dt`` defaults to
    safety_factor * dt_crit (global omega_max). x, y are displacements of the output node from its
    undeformed position; ``normal_force``/``friction_force`` sum over the slave nodes; ``slip_velocity`` and
    ``state`` are the primary contact node's. ``progress(done, total)`` is called between chunks.
    ``u0``/``v0`` (all DOFs) override the initial displacement/velocity. ``record_state`` stores u, v (all
    DOFs) at every sample (slow path, for tests).

    A thin wrapper of :func:`stickslip.fe.driver.drive`. It starts as :func:`stickslip.fe.explicit.integrate`
    and the scenes do (``DEFAULT_INITIAL_STATE``, the same step factor); ``blowup`` differs on purpose
    (1e3 mm, not 1e6); no second-half counts, and a blow-up reports the end of its chunk as the
    steps done (``n_steps``).
    """
    initial_state = run_settings(
        duration, safety_factor, initial_state, output_interval=output_interval, dt=dt
    ).initial_state
    dt_crit = stable_time_step(scene)
    dt, n_steps, every, n_out = schedule(duration, dt_crit, dt, safety_factor, output_interval)

    q_stat, N_stat = static_state(scene)
    u = q_stat.copy() if initial_state == "static" else np.zeros(scene.mesh.n_dof)
    v = np.zeros(scene.mesh.n_dof)
    for name, arr, target in (("u0", u0, u), ("v0", v0, v)):
        if arr is not None:
            arr = np.asarray(arr, float)
            if arr.shape != target.shape:
                raise ValueError(f"{name}: must have shape {target.shape}, got {arr.shape}")
            target[:] = np.where(scene.fixed, 0.0, arr)
    onode = (2 * scene.output_nodes).astype(np.int64)
    ow = np.asarray(scene.output_weights, float)
    pt = [float(ow @ arr[onode + k]) for arr in (u, v) for k in (0, 1)]
    out = np.zeros((n_out, 8))  # the node recorder writes the series by column
    ost = np.zeros(n_out, np.int8)
    has_contact = scene.contact_nodes.size > 0
    closed = has_contact and (initial_state != "static" or N_stat > 0)
    out[0] = (0.0, *pt, N_stat if initial_state == "static" else 0.0, 0.0, 0.0)
    if has_contact:
        c0 = 2 * scene.contact_nodes[scene.primary]
        out[0, 7] = float(scene.tangents[scene.primary] @ v[c0 : c0 + 2]) - scene.disc_speed
    ost[0] = STICK if closed else SEPARATED
    u_start, v_start = u.copy(), v.copy()
    structure, contact = quad_structure(scene, dt), node_contact(scene, dt)
    recorder = node_recorder(scene, out, ost)
    # The driver keeps the sampled states (sample_state: chunks of one output interval); no second-half
    # counts (halves off); a blow-up reports the end of its chunk as the steps done.
    run = drive(
        structure, contact, recorder, u, v, n_steps=n_steps, every=every, dt=dt, blowup=blowup,
        chunk=chunk, progress=progress, sample_state=record_state,
    )  # fmt: skip
    m = run.j
    res = pack_result(
        out.T, ost, run, n_steps=run.chunk_end, dt=dt, dt_crit=dt_crit, static_normal_force=N_stat,
        q_static=q_stat,
        q_samples=np.array(([u_start] + run.q_samples)[:m]) if record_state else None,
        v_samples=np.array(([v_start] + run.v_samples)[:m]) if record_state else None,
    )  # fmt: skip
    res.extra.update(
        model="continuum",
        mesh=f"{scene.mesh.nx}x{scene.mesh.ny}",
        output_node=scene.output_name,
        output_node_ids=scene.output_nodes.tolist(),
        initial_state=initial_state,
        damping_beta=scene.damping_beta,
        n_contact_nodes=int(scene.contact_nodes.size),
    )
    return res
