"""The one explicit central-difference engine of the FE models (numba), with pluggable pieces.

Every model advances its state with the same loop, :func:`run_steps`::

    v <- structure velocity update (internal and external force, damping)
    contact impulses on v (normal, then stick or slip), giving (normal force, friction force, state)
    u <- u + dt v
    every ``every``-th step: record a sample, stop if a displacement exceeds ``blowup`` (or is NaN)

What differs between models is data, and the type of that data picks the piece (as an element type picks
its shape functions in one assembly loop):

* structure: :class:`CsrStructure` (any linear system as G = dt M^-1 K in CSR form, Rayleigh damping:
  the frame-element beam's small dense Craig-Bampton reduction), :class:`BandStructure` (the same by
  diagonals, same bits, vectorised: the banded lumped-mass beam) or :class:`QuadStructure` (the continuum
  strip, internal force element by element with a lumped mass, half-step start);
* contact: :class:`KinematicPoint`, :class:`PenaltyPoint`, :class:`FixedNormalPoint` (one contact point
  given by vectors over the structure's coordinates, 2x2 Delassus solve) or :class:`SlaveNodes` (slave
  nodes of a lumped-mass mesh, kinematic or penalty, each node's impulses independent and exact);
* recorder: :class:`PointRecorder` (contact-point displacement/velocity as dot products, optional DOF
  samples) or :class:`NodeRecorder` (weighted output nodes, the primary contact node's slip velocity).

The generic functions :func:`velocity_update`, :func:`contact_impulse` and :func:`record_sample` dispatch on
those NamedTuple types at compile time (``numba.extending.overload``), so :func:`run_steps` is compiled once
per combination of piece types and cached on disk like any other function (a jitted function passed as an
argument would make numba recompile the driver in every process). All pieces live in this one module
because numba's on-disk cache of a function is invalidated only by edits to that function's own file.

Each piece repeats, operation for operation, the arithmetic of the per-law loops it replaced (bit identity
on one machine: ``benchmarks/check_engine_bits.py``; on any CPU ``tests/fe/test_engine_references.py``
holds it to stored references within measured round-off). The reference algorithm is the Python
loop :func:`stickslip.fe.explicit.integrate_python`; see :mod:`stickslip.fe.explicit` and
:mod:`stickslip.fe.continuum` for the contact treatment.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from numba.extending import overload

SEPARATED, STICK, SLIP = 0, 1, 2


# ------------------------------------------------------------------------------------------ piece data
class CsrStructure(NamedTuple):
    """v <- c1 v + c2 (af - G (u + beta v)): G = dt M^-1 K in CSR form, af = dt M^-1 f, mass-proportional
    damping in c1, c2, stiffness-proportional beta on the lagged half-step velocity."""

    indptr: np.ndarray
    indices: np.ndarray
    data: np.ndarray
    af: np.ndarray
    c1: float
    c2: float
    beta: float


class BandStructure(NamedTuple):
    """As :class:`CsrStructure` with G stored by diagonals: ``bands[d, i]`` = G[i, i + d - half]. Each row
    still sums its terms in column order, so for finite states the result equals the CSR kernel's bit for
    bit (the zeros inside the band add +-0 to a sum that starts at +0); the loop over rows within one
    diagonal vectorises, the CSR gather does not."""

    bands: np.ndarray  #: (2 half + 1, n)
    half: int
    af: np.ndarray
    c1: float
    c2: float
    beta: float
    padded: np.ndarray  #: (n + 2 half,) work vector, zero in its first and last ``half`` entries


class QuadStructure(NamedTuple):
    """v += h M^-1 (f_ext - K (u + beta v)), K element by element (``ke[kind[e]]`` is element e's 8 x 8
    stiffness, ``dofs[e]`` its DOFs), ``minv`` 1/m per DOF (0 where constrained); h = dt/2 on step 1 (the
    half-step start v_1/2 = v_0 + dt/2 a_0), else dt."""

    dofs: np.ndarray
    kind: np.ndarray
    ke: np.ndarray
    minv: np.ndarray
    fext: np.ndarray
    beta: float
    dt: float


class KinematicPoint(NamedTuple):
    """Exact non-penetration and exact stick at one point by a 2x2 Delassus impulse solve. Contact vectors
    compressed on their non-zero coordinates ``ci`` (cn, ct), M^-1 c on ``mi`` (Mcn, Mct)."""

    ci: np.ndarray
    cn: np.ndarray
    ct: np.ndarray
    mi: np.ndarray
    Mcn: np.ndarray
    Mct: np.ndarray
    Wnn: float
    Wnt: float
    Wtt: float
    det: float  #: Wnn Wtt - Wnt^2
    mu_s: float
    speeds: np.ndarray  #: friction table |v_r| [mm s-1]
    mu: np.ndarray  #: friction table mu
    V: float  #: disc surface speed
    g0: float  #: initial gap
    dt: float


class PenaltyPoint(NamedTuple):
    """Normal impulse kp * penetration(u_n) * dt at one point, then stick/slip as :class:`KinematicPoint`."""

    ci: np.ndarray
    cn: np.ndarray
    ct: np.ndarray
    mi: np.ndarray
    Mcn: np.ndarray
    Mct: np.ndarray
    Wtt: float
    mu_s: float
    speeds: np.ndarray
    mu: np.ndarray
    V: float
    g0: float
    kp: float
    dt: float


class FixedNormalPoint(NamedTuple):
    """Prescribed normal force N at one point (no separation possible), then stick/slip."""

    ci: np.ndarray
    ct: np.ndarray
    mi: np.ndarray
    Mcn: np.ndarray
    Mct: np.ndarray
    Wtt: float
    mu_s: float
    speeds: np.ndarray
    mu: np.ndarray
    V: float
    N: float
    dt: float


class SlaveNodes(NamedTuple):
    """Slave nodes (x DOF ``cdof[c]``, y DOF next) with fixed normals ``cn`` and surface directions ``ct``
    (n_c, 2), initial gaps ``cg0``, lumped masses ``cm``; kinematic (predictor-corrector) impulses, or with
    ``kp`` > 0 a penalty normal force kp * penetration(u_n) (explicit). The state reported is node
    ``primary``'s (0 if it is not a slave node)."""

    cdof: np.ndarray
    cn: np.ndarray
    ct: np.ndarray
    cg0: np.ndarray
    cm: np.ndarray
    V: float
    speeds: np.ndarray
    mu: np.ndarray
    primary: int
    dt: float
    kp: float  #: 0: kinematic


class PointRecorder(NamedTuple):
    """Sample j into ``out[:, j]`` (t, cx.u, cy.u, cx.v, cy.v, normal force, friction force, ct.v - V) and
    ``state[j]``; with ``keep_dofs``, u and v of the DOFs ``dofs`` into ``q[j]``, ``qd[j]``."""

    out: np.ndarray  #: (8, n_out)
    state: np.ndarray
    cx: np.ndarray
    cy: np.ndarray
    ci: np.ndarray
    ct: np.ndarray  #: compressed on ci
    V: float
    keep_dofs: bool
    q: np.ndarray
    qd: np.ndarray
    dofs: np.ndarray


class NodeRecorder(NamedTuple):
    """Sample j into ``out[j, :]`` (t, x, y, vx, vy of "node 1" = sum_k ow[k] node onode[k] (x DOF index),
    total normal force, total friction force, slip velocity of the primary contact node) and ``state[j]``."""

    out: np.ndarray  #: (n_out, 8)
    state: np.ndarray
    onode: np.ndarray
    ow: np.ndarray
    pdof: int  #: x DOF of the primary contact node, -1 if none
    pt: np.ndarray  #: its surface direction (2,)
    V: float


# ------------------------------------------------------------------------------------- small helpers
@njit(cache=True)
def _dot(a, b):
    s = 0.0
    for i in range(a.size):
        s += a[i] * b[i]
    return s


@njit(cache=True)
def _sdot(idx, a, x):
    """sum_k a[k] x[idx[k]] (contact vectors are stored compressed on their non-zero DOFs)."""
    s = 0.0
    for k in range(idx.size):
        s += a[k] * x[idx[k]]
    return s


@njit(cache=True)
def _saxpy(idx, a, c, x):
    """x[idx] += c a."""
    for k in range(idx.size):
        x[idx[k]] += c * a[k]


@njit(cache=True)
def friction_coefficient(speed, speeds, mu):
    """mu(|speed|): linear interpolation in the table, constant beyond its ends."""
    s = abs(speed)
    n = speeds.size
    if n == 1 or s <= speeds[0]:
        return mu[0]
    if s >= speeds[n - 1]:
        return mu[n - 1]
    k = 1
    while speeds[k] < s:
        k += 1
    w = (s - speeds[k - 1]) / (speeds[k] - speeds[k - 1])
    return mu[k - 1] + w * (mu[k] - mu[k - 1])


@njit(cache=True)
def _all_below(u, bound):
    """False if any |u_i| >= bound or is NaN."""
    for i in range(u.size):
        if not abs(u[i]) < bound:
            return False
    return True


# ---------------------------------------------------------------------------------- structure kernels
@njit(cache=True)
def _lagged(u, v, beta, out, offset):
    """out[offset + i] = u_i + beta v_i (u_i alone without damping): what the stiffness acts on, with
    stiffness-proportional damping on the lagged half-step velocity."""
    if beta != 0.0:
        for i in range(u.size):
            out[offset + i] = u[i] + beta * v[i]
    else:
        for i in range(u.size):
            out[offset + i] = u[i]


@njit(cache=True)
def csr_velocity_update(n, u, v, w, f, s):
    _lagged(u, v, s.beta, w, 0)
    indptr, indices, data, af, c1, c2 = s.indptr, s.indices, s.data, s.af, s.c1, s.c2
    for i in range(u.size):
        acc = 0.0
        for k in range(indptr[i], indptr[i + 1]):
            acc += data[k] * w[indices[k]]
        v[i] = c1 * v[i] + c2 * (af[i] - acc)


@njit(cache=True)
def band_velocity_update(n, u, v, w, f, s):
    h, wp, bands = s.half, s.padded, s.bands
    _lagged(u, v, s.beta, wp, h)
    acc = f
    acc[:] = 0.0
    for d in range(bands.shape[0]):  # columns in ascending order within every row
        row = bands[d]
        for i in range(u.size):
            acc[i] += row[i] * wp[i + d]
    af, c1, c2 = s.af, s.c1, s.c2
    for i in range(u.size):
        v[i] = c1 * v[i] + c2 * (af[i] - acc[i])


@njit(cache=True)
def quad_velocity_update(n, u, v, w, f, s):
    h = 0.5 * s.dt if n == 1 else s.dt
    dofs, kind, ke, minv = s.dofs, s.kind, s.ke, s.minv
    _lagged(u, v, s.beta, w, 0)
    f[:] = s.fext
    fe = np.empty(8)  # local, so that the compiler keeps the 8 sums in registers
    for e in range(dofs.shape[0]):
        K = ke[kind[e]]
        fe[:] = 0.0
        for b in range(8):  # column-wise with K symmetric: 8 independent sums, vectorisable as written
            ub = w[dofs[e, b]]
            for a in range(8):
                fe[a] += K[b, a] * ub
        for a in range(8):
            f[dofs[e, a]] -= fe[a]
    for i in range(u.size):
        v[i] += h * minv[i] * f[i]


# ------------------------------------------------------------------------------------ contact kernels
@njit(cache=True)
def _point_tangential(v, Pn, c):
    """Stick/slip tangential impulse once the normal impulse Pn > 0 is applied; updates v."""
    wt = _sdot(c.ci, c.ct, v)
    Pt = (c.V - wt) / c.Wtt
    if abs(Pt) <= c.mu_s * Pn:
        state = STICK
    else:
        Pt = (1.0 if Pt > 0 else -1.0) * np.interp(abs(wt - c.V), c.speeds, c.mu) * Pn
        state = SLIP
    _saxpy(c.mi, c.Mct, Pt, v)
    return Pt, state


@njit(cache=True)
def kinematic_point_impulse(u, v, c):
    Pn = 0.0
    Pt = 0.0
    dt = c.dt
    gtrial = c.g0 + _sdot(c.ci, c.cn, u) + dt * _sdot(c.ci, c.cn, v)
    if gtrial < 0.0:
        Wnn, Wnt, Wtt, det, V = c.Wnn, c.Wnt, c.Wtt, c.det, c.V
        wt = _sdot(c.ci, c.ct, v)
        bn = -gtrial / dt
        bt = V - wt
        Pn = (Wtt * bn - Wnt * bt) / det
        Pt = (Wnn * bt - Wnt * bn) / det
        if Pn > 0.0 and abs(Pt) <= c.mu_s * Pn:
            state = STICK
        else:
            s = 1.0 if Pt > 0 else -1.0
            mu = np.interp(abs(wt - V), c.speeds, c.mu)
            Pn = bn / (Wnn + Wnt * s * mu)
            if Pn <= 0.0:  # friction-driven lift: normal-only correction
                Pn = bn / Wnn
                mu = 0.0
            Pt = s * mu * Pn
            state = SLIP
        _saxpy(c.mi, c.Mcn, Pn, v)
        _saxpy(c.mi, c.Mct, Pt, v)
    else:
        state = SEPARATED
    return Pn / dt, Pt / dt, state


@njit(cache=True)
def penalty_point_impulse(u, v, c):
    Pt = 0.0
    g = c.g0 + _sdot(c.ci, c.cn, u)
    Pn = -c.kp * g * c.dt if g < 0.0 else 0.0
    if Pn > 0.0:
        _saxpy(c.mi, c.Mcn, Pn, v)
        Pt, state = _point_tangential(v, Pn, c)
    else:
        state = SEPARATED
    return Pn / c.dt, Pt / c.dt, state


@njit(cache=True)
def fixed_normal_point_impulse(u, v, c):
    Pt = 0.0
    Pn = c.N * c.dt
    _saxpy(c.mi, c.Mcn, Pn, v)
    if Pn > 0.0:
        Pt, state = _point_tangential(v, Pn, c)
    else:
        state = SEPARATED
    return Pn / c.dt, Pt / c.dt, state


@njit(cache=True)
def _node_friction(v, dx, dy, nx, ny, tx, ty, m, pn, wt, V, speeds, mu):
    """Stick or slip impulse of one slave node with normal impulse pn > 0; applies both to v."""
    mu_s = mu[0]
    pt = m * (V - wt)
    if abs(pt) <= mu_s * pn:
        st = STICK
    else:
        s = 1.0 if pt > 0.0 else -1.0
        pt = s * friction_coefficient(wt - V, speeds, mu) * pn
        st = SLIP
    v[dx] += (pn * nx + pt * tx) / m
    v[dy] += (pn * ny + pt * ty) / m
    return pt, st


@njit(cache=True)
def node_impulses(u, v, c):
    """Every slave node's impulses: kinematic (``kp`` 0: the free predictor's gap closed exactly) or
    penalty (kp * penetration at u_n, explicit)."""
    dt, kp = c.dt, c.kp
    fn_tot = 0.0
    ft_tot = 0.0
    state = SEPARATED
    for k in range(c.cdof.size):
        dx = c.cdof[k]
        dy = dx + 1
        nx, ny = c.cn[k, 0], c.cn[k, 1]
        tx, ty = c.ct[k, 0], c.ct[k, 1]
        wt = tx * v[dx] + ty * v[dy]  # n . t = 0: a normal impulse would leave wt unchanged
        st = SEPARATED
        g = c.cg0[k] + nx * u[dx] + ny * u[dy]
        if kp == 0.0:
            g = g + dt * (nx * v[dx] + ny * v[dy])
        if g < 0.0:
            m = c.cm[k]
            pn = -kp * g * dt if kp != 0.0 else -m * g / dt
            pt, st = _node_friction(v, dx, dy, nx, ny, tx, ty, m, pn, wt, c.V, c.speeds, c.mu)
            fn_tot += pn / dt
            ft_tot += pt / dt
        if k == c.primary:
            state = st
    return fn_tot, ft_tot, state


# ------------------------------------------------------------------------------------------ recorders
@njit(cache=True)
def record_point(j, t, u, v, fn, ft, state, r):
    if j >= r.state.size:
        return j
    out = r.out
    out[0, j] = t
    out[1, j] = _dot(r.cx, u)
    out[2, j] = _dot(r.cy, u)
    out[3, j] = _dot(r.cx, v)
    out[4, j] = _dot(r.cy, v)
    out[5, j] = fn
    out[6, j] = ft
    out[7, j] = _sdot(r.ci, r.ct, v) - r.V
    r.state[j] = state
    if r.keep_dofs:
        for k in range(r.dofs.size):
            r.q[j, k] = u[r.dofs[k]]
            r.qd[j, k] = v[r.dofs[k]]
    return j + 1


@njit(cache=True)
def record_node(j, t, u, v, fn, ft, state, r):
    if j >= r.state.size:
        return j
    out = r.out
    out[j, 0] = t
    x = y = vx = vy = 0.0
    for k in range(r.onode.size):
        d = r.onode[k]
        w = r.ow[k]
        x += w * u[d]
        y += w * u[d + 1]
        vx += w * v[d]
        vy += w * v[d + 1]
    out[j, 1] = x
    out[j, 2] = y
    out[j, 3] = vx
    out[j, 4] = vy
    out[j, 5] = fn
    out[j, 6] = ft
    vr = 0.0
    if r.pdof >= 0:
        d = r.pdof
        vr = r.pt[0] * v[d] + r.pt[1] * v[d + 1] - r.V
    out[j, 7] = vr
    r.state[j] = state
    return j + 1


# ---------------------------------------------------------------------- dispatch on the data's type
STRUCTURES = {
    CsrStructure: csr_velocity_update,
    BandStructure: band_velocity_update,
    QuadStructure: quad_velocity_update,
}
CONTACTS = {
    KinematicPoint: kinematic_point_impulse,
    PenaltyPoint: penalty_point_impulse,
    FixedNormalPoint: fixed_normal_point_impulse,
    SlaveNodes: node_impulses,
}
RECORDERS = {PointRecorder: record_point, NodeRecorder: record_node}


def _piece(table, data):
    """The kernel registered for a numba NamedTuple type (None: not ours, numba reports the typing error)."""
    return table.get(getattr(data, "instance_class", None))


def velocity_update(n, u, v, w, f, s):
    """Step n's velocity update of v (in place; w, f: work vectors) by the kernel of structure s's type."""
    return STRUCTURES[type(s)](n, u, v, w, f, s)


def contact_impulse(u, v, c):
    """Contact impulses on v (in place) -> (normal force, friction force, state), by contact c's type."""
    return CONTACTS[type(c)](u, v, c)


def record_sample(j, t, u, v, fn, ft, state, r):
    """Store sample j if there is room -> next free index, by the recorder r's type."""
    return RECORDERS[type(r)](j, t, u, v, fn, ft, state, r)


# Each overload hands numba the kernel's own Python function: a wrapper (``lambda ...: kernel(...)``) would
# make numba take and release a reference to every array of the data tuples at every step (10-30 % slower).
@overload(velocity_update, jit_options={"cache": True})
def _velocity_update(n, u, v, w, f, s):
    kernel = _piece(STRUCTURES, s)
    if kernel is not None:
        return kernel.py_func


@overload(contact_impulse, jit_options={"cache": True})
def _contact_impulse(u, v, c):
    kernel = _piece(CONTACTS, c)
    if kernel is not None:
        return kernel.py_func


@overload(record_sample, jit_options={"cache": True})
def _record_sample(j, t, u, v, fn, ft, state, r):
    kernel = _piece(RECORDERS, r)
    if kernel is not None:
        return kernel.py_func


# ---------------------------------------------------------------------------------------- the driver
@njit(cache=True)
def run_steps(first, last, every, j, dt, blowup, u, v, counts, structure, contact, recorder):
    """Advance steps ``first .. last`` (inclusive) in place; sample every ``every``-th step into the
    recorder from index ``j``; ``counts[state]`` counts the steps per contact state. Returns (next sample
    index, last step done, True if a displacement exceeded ``blowup`` (checked at sampled steps))."""
    w = np.empty_like(u)  # work vectors of the structure kernels
    f = np.empty_like(u)
    n = first - 1
    for n in range(first, last + 1):
        velocity_update(n, u, v, w, f, structure)
        fn, ft, state = contact_impulse(u, v, contact)
        for i in range(u.size):
            u[i] += dt * v[i]
        counts[state] += 1
        if n % every == 0:
            j = record_sample(j, n * dt, u, v, fn, ft, state, recorder)
            if not _all_below(u, blowup):
                return j, n, True
    return j, n, False
