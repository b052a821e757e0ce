"""Explicit central-difference integration with contact and tabulated friction.

The structure is any linear mechanical system (full beam or reduced model) given by dense M, K, a constant
load f and the contact-point vectors; the only nonlinearity is at the contact point:

* ``kinematic``: predictor-corrector as in explicit codes. The free predictor u_{n+1} is computed; if it
  penetrates, normal and tangential impulses P = W^-1 b are solved from the 2x2 Delassus matrix
  W = C^T M^-1 C so that the corrected gap is exactly zero and (trial stick) the tangential velocity equals
  the disc surface speed. If |P_t| > mu(0) P_n the step slips: P_t = sign(P_t^stick) mu(|v_r|) P_n and P_n
  is re-solved with that friction. Stick therefore has zero slip velocity to round-off (no creep) and
  slip impulses never overshoot past sticking.
* ``penalty``: normal force k_p * penetration evaluated at u_n (explicit), same tangential treatment.
* ``fixed_normal``: normal force held at a prescribed value (Section 10, no separation possible).

Velocities live at half steps: v_{n+1/2} = v_{n-1/2} + dt M^-1 (f - K u_n) + M^-1 C P,
u_{n+1} = u_n + dt v_{n+1/2}.
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sps

from ..model.params import checked_arguments
from . import engine
from .driver import SEPARATED, SLIP, STICK, ExplicitResult, Run, critical_step, drive, pack_result, schedule
from .params import DEFAULT_INITIAL_STATE, DEFAULT_SAFETY_FACTOR, FrictionTable, run_settings

__all__ = ["SEPARATED", "SLIP", "STICK", "ExplicitResult", "integrate", "integrate_python"]


@dataclass(frozen=True)
class System:
    """Linear structure + contact-point vectors (any basis: physical DOFs or reduced coordinates)."""

    M: np.ndarray  #: mass [t]
    K: np.ndarray  #: stiffness [N mm-1]
    f: np.ndarray  #: constant load (gravity) [N]
    c_x: np.ndarray  #: horizontal displacement of the contact point = c_x . q [mm]
    c_y: np.ndarray  #: vertical displacement of the contact point
    c_n: np.ndarray  #: gap increment = c_n . q (normal along the outward disc normal)
    c_t: np.ndarray  #: tangential displacement along the disc surface velocity
    label: str = "full"

    @property
    def n(self) -> int:
        return self.K.shape[0]


@dataclass(frozen=True)
class ContactLaw:
    method: str  #: kinematic | penalty | fixed_normal
    friction: FrictionTable
    disc_speed: float  #: disc surface speed V [mm s-1]
    penalty_stiffness: float = 0.0  #: [N mm-1]
    fixed_normal_force: float = 0.0  #: [N], method fixed_normal only
    gap0: float = 0.0  #: initial gap [mm]


def contact_omega(system: System, law: ContactLaw) -> float:
    """Angular frequency [rad s-1] of the penalty spring on the contact point's own effective mass,
    sqrt(k_p c_n^T M^-1 (c_n + mu_s c_t)) (the friction it transmits included); 0 for the other methods."""
    if law.method != "penalty":
        return 0.0
    cn, ct = system.c_n, system.c_t
    w = np.linalg.solve(system.M, cn + law.friction.static * ct) if system.n else cn
    return float(math.sqrt(max(law.penalty_stiffness * float(cn @ w), 0.0)))


def omega_max(system: System, law: ContactLaw) -> float:
    """Highest angular frequency [rad s-1] for the central-difference limit. Penalty contact: the larger of
    the assembled system's (penalty spring included) and the bound sqrt(omega_K^2 + omega_c^2) of the
    structure plus the contact spring on its own (explicit codes add the contact's frequency to the
    element's: the switched spring must be resolved on its own, not only inside the closed system)."""
    K = system.K
    n = K.shape[0]
    if law.method == "penalty":
        Kc = K + law.penalty_stiffness * np.outer(system.c_n, system.c_n)
        w2c = sla.eigh(Kc, system.M, eigvals_only=True, subset_by_index=[n - 1, n - 1])[0]
        w2k = sla.eigh(K, system.M, eigvals_only=True, subset_by_index=[n - 1, n - 1])[0]
        w2 = max(w2c, max(w2k, 0.0) + contact_omega(system, law) ** 2)
        return float(math.sqrt(max(w2, 0.0)))
    w2 = sla.eigh(K, system.M, eigvals_only=True, subset_by_index=[n - 1, n - 1])[0]
    return float(math.sqrt(max(w2, 0.0)))


def stable_time_step(system: System, law: ContactLaw) -> float:
    """Central-difference stability limit dt_crit = 2 / omega_max (undamped)."""
    return 2.0 / omega_max(system, law)


def static_state(system: System, law: ContactLaw) -> tuple[np.ndarray, float]:
    """Gravity equilibrium with the contact closed; returns (q, normal force [N])."""
    K, f, cn = system.K, system.f, system.c_n
    if law.method == "kinematic":
        n = system.n
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = K
        A[:n, n] = -cn
        A[n, :n] = cn
        sol = np.linalg.solve(A, np.concatenate([f, [-law.gap0]]))
        q, N = sol[:n], float(sol[n])
        if N < 0:  # gravity would lift the beam off: free equilibrium
            q, N = np.linalg.solve(K, f), 0.0
        return q, N
    if law.method == "penalty":
        q = np.linalg.solve(
            K + law.penalty_stiffness * np.outer(cn, cn), f - law.penalty_stiffness * law.gap0 * cn
        )
        g = law.gap0 + cn @ q
        if g >= 0:
            return np.linalg.solve(K, f), 0.0
        return q, float(-law.penalty_stiffness * g)
    q = np.linalg.solve(K, f + law.fixed_normal_force * cn)
    return q, float(law.fixed_normal_force)


@dataclass
class _Prepared:
    dt: float
    dt_crit: float
    n_steps: int
    every: int
    n_out: int
    G: np.ndarray
    af: np.ndarray
    Mcn: np.ndarray
    Mct: np.ndarray
    Wnn: float
    Wnt: float
    Wtt: float
    c1: float
    c2: float
    u: np.ndarray
    v: np.ndarray
    q_stat: np.ndarray
    N_stat: float


def _prepare(system, law, duration, dt, safety_factor, output_interval, initial_state, q0, v0, alpha, beta):
    initial_state = run_settings(
        duration, safety_factor, initial_state, output_interval=output_interval, dt=dt,
        mass_damping=alpha, stiffness_damping=beta,
    ).initial_state  # fmt: skip
    dt_crit = stable_time_step(system, law)
    if beta > 0:  # lagged stiffness damping
        dt_crit = critical_step(2.0 / dt_crit, beta)
    dt, n_steps, every, n_out = schedule(duration, dt_crit, dt, safety_factor, output_interval)
    M, K, f = system.M, system.K, system.f
    if np.allclose(M, np.diag(np.diag(M))):
        Minv = np.diag(1.0 / np.diag(M))
    else:
        Minv = np.linalg.inv(M)
    cn, ct = system.c_n, system.c_t
    Mcn, Mct = Minv @ cn, Minv @ ct
    q_stat, N_stat = static_state(system, law)
    if q0 is not None:
        u = np.array(q0, float)
    elif initial_state == "static":
        u = q_stat.copy()
    else:
        u = np.zeros(system.n)
    v = np.zeros(system.n) if v0 is None else np.array(v0, float)
    return _Prepared(
        dt=dt,
        dt_crit=dt_crit,
        n_steps=n_steps,
        every=every,
        n_out=n_out,
        G=dt * Minv @ K,
        af=dt * Minv @ f,
        Mcn=Mcn,
        Mct=Mct,
        Wnn=float(cn @ Mcn),
        Wnt=float(cn @ Mct),
        Wtt=float(ct @ Mct),
        c1=(1 - 0.5 * alpha * dt) / (1 + 0.5 * alpha * dt),
        c2=1.0 / (1 + 0.5 * alpha * dt),
        u=u,
        v=v,
        q_stat=q_stat,
        N_stat=N_stat,
    )


def _record0(pr, system, law, out, st, qs, vs, rec=None):
    u, v = pr.u, pr.v
    out[:, 0] = (
        0.0,
        system.c_x @ u,
        system.c_y @ u,
        system.c_x @ v,
        system.c_y @ v,
        pr.N_stat,
        0.0,
        system.c_t @ v - law.disc_speed,
    )
    st[0] = STICK if pr.N_stat > 0 else SEPARATED
    if qs is not None:
        qs[0], vs[0] = (u, v) if rec is None else (u[rec], v[rec])


def csr_structure(pr: _Prepared, stiffness_damping: float) -> engine.CsrStructure:
    """The engine's structure piece: G = dt M^-1 K in CSR form (zeros dropped), damping as prepared."""
    G = sps.csr_matrix(pr.G)
    G.eliminate_zeros()
    return engine.CsrStructure(
        G.indptr.astype(np.int64), G.indices.astype(np.int64), G.data.astype(np.float64), pr.af,
        pr.c1, pr.c2, float(stiffness_damping),
    )  # fmt: skip


def band_structure(pr: _Prepared, stiffness_damping: float) -> engine.BandStructure:
    """The engine's structure piece with G stored by diagonals (same result as ``csr_structure``)."""
    G = np.asarray(pr.G, dtype=np.float64)
    n = G.shape[0]
    half = _half_bandwidth(G)
    bands = np.zeros((2 * half + 1, n))
    for d in range(-half, half + 1):
        rows = np.arange(max(0, -d), min(n, n - d))
        bands[d + half, rows] = G[rows, rows + d]
    padded = np.zeros(n + 2 * half)
    return engine.BandStructure(bands, half, pr.af, pr.c1, pr.c2, float(stiffness_damping), padded)


def _half_bandwidth(G: np.ndarray) -> int:
    rows, cols = np.nonzero(G)
    return int(np.abs(rows - cols).max()) if rows.size else 0


def beam_structure(pr: _Prepared, stiffness_damping: float):
    """The faster structure piece for G: by diagonals where the band is at most a quarter of the matrix
    (the lumped-mass beam: 9 diagonals of 60 DOFs, a third less CPU per step), else CSR (small dense
    reduced models, or a consistent mass, which makes M^-1 K dense). Both give the same bits."""
    n = pr.G.shape[0]
    if 4 * (2 * _half_bandwidth(pr.G) + 1) <= n:
        return band_structure(pr, stiffness_damping)
    return csr_structure(pr, stiffness_damping)


def point_contact(system: System, law: ContactLaw, pr: _Prepared):
    """The engine's contact piece of ``law.method``, its vectors compressed on their non-zero coordinates."""
    cn, ct = (np.ascontiguousarray(a, dtype=float) for a in (system.c_n, system.c_t))
    ci = np.flatnonzero((cn != 0) | (ct != 0)).astype(np.int64)
    mi = np.flatnonzero((pr.Mcn != 0) | (pr.Mct != 0)).astype(np.int64)
    common = dict(
        ci=ci, ct=ct[ci], mi=mi, Mcn=pr.Mcn[mi], Mct=pr.Mct[mi], Wtt=pr.Wtt, mu_s=law.friction.static,
        speeds=np.asarray(law.friction.speeds, float), mu=np.asarray(law.friction.mu, float),
        V=law.disc_speed, dt=pr.dt,
    )  # fmt: skip
    if law.method == "kinematic":
        det = pr.Wnn * pr.Wtt - pr.Wnt * pr.Wnt
        return engine.KinematicPoint(cn=cn[ci], Wnn=pr.Wnn, Wnt=pr.Wnt, det=det, g0=law.gap0, **common)
    if law.method == "penalty":
        return engine.PenaltyPoint(cn=cn[ci], g0=law.gap0, kp=law.penalty_stiffness, **common)
    if law.method == "fixed_normal":
        return engine.FixedNormalPoint(N=law.fixed_normal_force, **common)
    raise ValueError(f"method: unknown contact method {law.method!r}")


def point_recorder(
    system: System, law: ContactLaw, out, st, record_state, qs, vs, rec
) -> engine.PointRecorder:
    """The engine's recorder of the contact point (and of the DOFs ``rec`` with ``record_state``)."""
    cx, cy, ct = (np.ascontiguousarray(a, dtype=float) for a in (system.c_x, system.c_y, system.c_t))
    cn = np.ascontiguousarray(system.c_n, dtype=float)
    ci = np.flatnonzero((cn != 0) | (ct != 0)).astype(np.int64)
    return engine.PointRecorder(out, st, cx, cy, ci, ct[ci], law.disc_speed, bool(record_state), qs, vs, rec)


@checked_arguments(backend=Literal["compiled", "python"])
def integrate(
    system: System,
    law: ContactLaw,
    duration: float,
    *,
    dt: float | None = None,
    safety_factor: float = DEFAULT_SAFETY_FACTOR,
    output_interval: float | None = None,
    initial_state: str = DEFAULT_INITIAL_STATE,
    q0: np.ndarray | None = None,
    v0: np.ndarray | None = None,
    mass_damping: float = 0.0,
    stiffness_damping: float = 0.0,
    record_state: bool = False,
    blowup: float = 1e6,
    progress=None,
    backend: str = "compiled",
    chunk: int = 200_000,
    record_dofs: np.ndarray | None = None,
) -> ExplicitResult:
    """Integrate ``duration`` seconds. ``dt`` defaults to safety_factor * dt_crit.

    ``initial_state``: ``static`` (gravity equilibrium in contact) or ``drop`` (alias ``undeformed``:
    undeformed, at rest, gravity applied at t = 0, as an ABAQUS/Explicit step starts).
    ``mass_damping`` alpha [s-1] and ``stiffness_damping`` beta [s] are Rayleigh coefficients.
    ``backend``: ``compiled`` (the numba engine :func:`stickslip.fe.engine.run_steps`) or ``python`` (the
    reference loop, same algorithm step for step). ``progress(done, total)``, if given, is called between
    chunks of ``chunk`` steps (compiled) or every 10 000 steps (python).

    ``record_state`` keeps q and v at every output sample: all DOFs, or only ``record_dofs`` (compiled
    backend; the columns of ``q_samples`` / ``v_samples`` are then those DOFs in that order).

    Stops early (result flagged ``extra['diverged']``) if any displacement exceeds ``blowup`` mm.

    A thin wrapper of :func:`stickslip.fe.driver.drive`. It starts as
    :func:`stickslip.fe.continuum.integrate_continuum` and the scenes do (``DEFAULT_INITIAL_STATE``, the
    same step factor); ``blowup`` differs on purpose (1e6 mm, not 1e3: a beam run's growth is data). Its
    result counts the second half's states apart (``extra['second_half_counts']``) and a blow-up reports
    the sampled step at which it was found.
    """
    pr = _prepare(
        system, law, duration, dt, safety_factor, output_interval, initial_state, q0, v0,
        mass_damping, stiffness_damping,
    )  # fmt: skip
    if backend == "python":
        return _python_loop(system, law, pr, stiffness_damping, record_state, blowup, progress)
    out = np.zeros((8, pr.n_out))  # the point recorder writes the series by row
    st = np.zeros(pr.n_out, dtype=np.int8)
    rec = np.asarray(np.arange(system.n) if record_dofs is None else record_dofs, dtype=np.int64)
    qs = np.zeros((pr.n_out, rec.size)) if record_state else np.zeros((1, 1))
    vs = np.zeros((pr.n_out, rec.size)) if record_state else np.zeros((1, 1))
    _record0(pr, system, law, out, st, qs if record_state else None, vs if record_state else None, rec)
    recorder = point_recorder(system, law, out, st, record_state, qs, vs, rec)
    structure, contact = beam_structure(pr, stiffness_damping), point_contact(system, law, pr)
    # The point recorder keeps the sampled states itself (sample_state off); the second half's states are
    # counted apart (halves); a blow-up reports the sampled step at which it was found.
    run = drive(
        structure, contact, recorder, pr.u.copy(), pr.v.copy(), n_steps=pr.n_steps, every=pr.every,
        dt=pr.dt, blowup=blowup, chunk=chunk, progress=progress, halves=True,
    )  # fmt: skip
    return _packed(pr, out, st, run, qs if record_state else None, vs if record_state else None)


def _packed(pr: _Prepared, out, st, run: Run, qs, vs) -> ExplicitResult:
    """Either loop's result: its steps done are the last step it ran (a blow-up's sampled step)."""
    return pack_result(
        out, st, run, n_steps=run.n_done, dt=pr.dt, dt_crit=pr.dt_crit, static_normal_force=pr.N_stat,
        q_static=pr.q_stat, q_samples=None if qs is None else qs[: run.j],
        v_samples=None if vs is None else vs[: run.j],
    )  # fmt: skip


def _python_loop(system, law, pr: _Prepared, stiffness_damping, record_state, blowup, progress):
    """The per-step Python loop of :func:`integrate` (slow; the oracle of the compiled engine)."""
    dt, n_steps, every, n_out = pr.dt, pr.n_steps, pr.every, pr.n_out
    G, af, Mcn, Mct = pr.G, pr.af, pr.Mcn, pr.Mct
    Wnn, Wnt, Wtt = pr.Wnn, pr.Wnt, pr.Wtt
    det = Wnn * Wtt - Wnt * Wnt
    c1, c2, beta = pr.c1, pr.c2, stiffness_damping
    cn, ct, cx, cy = system.c_n, system.c_t, system.c_x, system.c_y
    mu_s = law.friction.static
    mu_fn = law.friction
    V = law.disc_speed
    g0 = law.gap0
    kp = law.penalty_stiffness
    kin, pen = law.method == "kinematic", law.method == "penalty"
    u, v = pr.u.copy(), pr.v.copy()
    out = np.zeros((8, n_out))
    st = np.zeros(n_out, dtype=np.int8)
    qs = np.zeros((n_out, system.n)) if record_state else None
    vs = np.zeros((n_out, system.n)) if record_state else None
    _record0(pr, system, law, out, st, qs, vs)
    counts = [0, 0, 0]
    first_half = [0, 0, 0]
    state = STICK
    j = 1
    n = 0
    diverged = False
    t0 = time.process_time()
    for n in range(1, n_steps + 1):
        if progress is not None and n % 10_000 == 0:
            progress(n, n_steps)
        v = c1 * v + c2 * (af - G @ (u + beta * v))
        Pn = Pt = 0.0
        if kin:
            gtrial = g0 + cn @ u + dt * (cn @ v)
            if gtrial < 0.0:
                wt = ct @ v
                bn = -gtrial / dt
                bt = V - wt
                Pn = (Wtt * bn - Wnt * bt) / det
                Pt = (Wnn * bt - Wnt * bn) / det
                if Pn > 0.0 and abs(Pt) <= mu_s * Pn:
                    state = STICK
                else:
                    s = 1.0 if Pt > 0 else -1.0
                    mu = mu_fn(wt - V)
                    Pn = bn / (Wnn + Wnt * s * mu)
                    if Pn <= 0.0:  # friction-driven lift: normal-only correction
                        Pn, mu = bn / Wnn, 0.0
                    Pt = s * mu * Pn
                    state = SLIP
                v = v + Pn * Mcn + Pt * Mct
            else:
                state = SEPARATED
        else:
            if pen:
                g = g0 + cn @ u
                Pn = -kp * g * dt if g < 0.0 else 0.0
                if Pn > 0.0:
                    v = v + Pn * Mcn
            else:
                Pn = law.fixed_normal_force * dt
                v = v + Pn * Mcn
            if Pn > 0.0:
                wt = ct @ v
                Pt = (V - wt) / Wtt
                if abs(Pt) <= mu_s * Pn:
                    state = STICK
                else:
                    Pt = (1.0 if Pt > 0 else -1.0) * mu_fn(wt - V) * Pn
                    state = SLIP
                v = v + Pt * Mct
            else:
                state = SEPARATED
        u = u + dt * v
        counts[state] += 1
        if n == n_steps // 2:
            first_half = list(counts)
        if n % every == 0:
            if j < n_out:
                out[:, j] = (n * dt, cx @ u, cy @ u, cx @ v, cy @ v, Pn / dt, Pt / dt, ct @ v - V)
                st[j] = state
                if record_state:
                    qs[j], vs[j] = u, v
                j += 1
            if not abs(u).max() < blowup:
                diverged = True
                break
    run = Run(j, n, n, diverged, np.array(counts), np.array(first_half), time.process_time() - t0)
    return _packed(pr, out, st, run, qs, vs)


#: The reference per-step Python loop, with :func:`integrate`'s own signature and setup (the oracle of the
#: compiled engine: tests/fe/test_engine.py compares them step by step).
integrate_python = functools.partial(integrate, backend="python")
