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

import math
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

from .params import FrictionTable

SEPARATED, STICK, SLIP = 0, 1, 2


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


def omega_max(system: System, law: ContactLaw) -> float:
    """Highest angular frequency [rad s-1] of the assembled system including the penalty spring."""
    K = system.K
    if law.method == "penalty":
        K = K + law.penalty_stiffness * np.outer(system.c_n, system.c_n)
    n = K.shape[0]
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
class ExplicitResult:
    t: np.ndarray
    x: np.ndarray  #: horizontal displacement of the contact point [mm]
    y: np.ndarray  #: vertical displacement [mm]
    vx: np.ndarray  #: horizontal velocity [mm s-1]
    vy: np.ndarray  #: vertical velocity [mm s-1]
    normal_force: np.ndarray  #: [N]
    friction_force: np.ndarray  #: friction on the beam along the disc velocity [N]
    slip_velocity: np.ndarray  #: beam minus disc tangential velocity [mm s-1]
    state: np.ndarray  #: 0 separated, 1 stick, 2 slip (per sample)
    dt: float
    dt_crit: float
    n_steps: int
    step_counts: dict  #: steps in each contact state over the whole run
    cpu_time: float
    static_normal_force: float
    q_static: np.ndarray
    q_samples: np.ndarray | None = None
    v_samples: np.ndarray | None = None
    extra: dict = field(default_factory=dict)

    def fractions(self) -> dict:
        tot = max(sum(self.step_counts.values()), 1)
        return {k: v / tot for k, v in self.step_counts.items()}


def integrate(
    system: System,
    law: ContactLaw,
    duration: float,
    *,
    dt: float | None = None,
    safety_factor: float = 0.9,
    output_interval: float | None = None,
    initial_state: str = "static",
    q0: np.ndarray | None = None,
    v0: np.ndarray | None = None,
    mass_damping: float = 0.0,
    record_state: bool = False,
    blowup: float = 1e6,
    progress=None,
) -> ExplicitResult:
    """Integrate ``duration`` seconds. ``dt`` defaults to safety_factor * 2/omega_max.

    ``progress(done, total)``, if given, is called every 10 000 steps with the step count.

    Stops early (result flagged ``extra['diverged']``) if any displacement exceeds ``blowup`` mm.
    """
    dt_crit = stable_time_step(system, law)
    if dt is None:
        dt = safety_factor * dt_crit
    n_steps = int(math.ceil(duration / dt - 1e-9))
    every = max(1, int(round((output_interval or dt) / dt)))
    n_out = n_steps // every + 1

    M, K, f = system.M, system.K, system.f
    Minv = np.linalg.inv(M)
    if np.allclose(M, np.diag(np.diag(M))):
        Minv = np.diag(1.0 / np.diag(M))
    G = dt * Minv @ K
    af = dt * Minv @ f
    cn, ct, cx, cy = system.c_n, system.c_t, system.c_x, system.c_y
    Mcn, Mct = Minv @ cn, Minv @ ct
    Wnn, Wnt, Wtt = float(cn @ Mcn), float(cn @ Mct), float(ct @ Mct)
    det = Wnn * Wtt - Wnt * Wnt
    mu_s = law.friction.static
    mu_fn = law.friction
    V = law.disc_speed
    g0 = law.gap0
    kp = law.penalty_stiffness
    method = law.method
    kin, pen = method == "kinematic", method == "penalty"
    damp = mass_damping > 0
    c1 = (1 - 0.5 * mass_damping * dt) / (1 + 0.5 * mass_damping * dt)
    c2 = 1.0 / (1 + 0.5 * mass_damping * dt)

    q_stat, N_stat = static_state(system, law)
    if q0 is not None:
        u = np.array(q0, float)
    elif initial_state == "static":
        u = q_stat.copy()
    else:
        u = np.zeros(system.n)
    v = np.zeros(system.n) if v0 is None else np.array(v0, float)

    out = {k: np.zeros(n_out) for k in ("t", "x", "y", "vx", "vy", "N", "F", "vr")}
    st = np.zeros(n_out, dtype=np.int8)
    qs = np.zeros((n_out, system.n)) if record_state else None
    vs = np.zeros((n_out, system.n)) if record_state else None
    counts = [0, 0, 0]
    Pn = Pt = 0.0
    state = STICK
    j = 0
    diverged = False

    def record(j, time_, state_, Pn_, Pt_):
        out["t"][j] = time_
        out["x"][j] = cx @ u
        out["y"][j] = cy @ u
        out["vx"][j] = cx @ v
        out["vy"][j] = cy @ v
        out["N"][j] = Pn_ / dt
        out["F"][j] = Pt_ / dt
        out["vr"][j] = ct @ v - V
        st[j] = state_
        if record_state:
            qs[j] = u
            vs[j] = v

    record(0, 0.0, STICK if N_stat > 0 else SEPARATED, N_stat * dt, 0.0)
    j = 1
    t0 = time.process_time()
    for n in range(1, n_steps + 1):
        if progress is not None and n % 10_000 == 0:
            progress(n, n_steps)
        if damp:
            v = c1 * v + c2 * (af - G @ u)
        else:
            v = v + af - G @ u
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
        if n % every == 0:
            if j < n_out:
                record(j, n * dt, state, Pn, Pt)
                j += 1
            if not abs(u).max() < blowup:
                diverged = True
                break
    cpu = time.process_time() - t0
    m = j
    res = ExplicitResult(
        t=out["t"][:m],
        x=out["x"][:m],
        y=out["y"][:m],
        vx=out["vx"][:m],
        vy=out["vy"][:m],
        normal_force=out["N"][:m],
        friction_force=out["F"][:m],
        slip_velocity=out["vr"][:m],
        state=st[:m],
        dt=dt,
        dt_crit=dt_crit,
        n_steps=n,
        step_counts={"separation": counts[0], "stick": counts[1], "slip": counts[2]},
        cpu_time=cpu,
        static_normal_force=N_stat,
        q_static=q_stat,
        q_samples=None if qs is None else qs[:m],
        v_samples=None if vs is None else vs[:m],
    )
    res.extra["diverged"] = diverged
    return res
