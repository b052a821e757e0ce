"""Complex-eigenvalue stability of steady sliding, linearised about the sliding equilibrium.

Steady sliding: beam at rest, disc surface moving at V, friction F_t = mu(V) N0 along t. With slip speed
s = V - c_t.qdot and N = N0 + dN, dF_t = mu dN - N0 mu'(V) c_t.dqdot, so

    M q'' + N0 mu' c_t c_t^T q' + K q - (c_n + mu c_t) dN = 0,

with dN = -k_p c_n^T q (penalty), dN a multiplier enforcing c_n^T q = 0 (kinematic), dN = 0 (fixed normal).
mu' < 0 is the negative damping of the falling friction law; mu c_t c_n^T is the non-symmetric
(circulatory) friction coupling that a tilted contact (angle != 0) feeds into the transverse modes.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
import scipy.linalg as sla

from ..model.params import checked_arguments
from .explicit import ContactLaw, System, integrate, static_state
from .metrics import dominant_frequency, window_envelope


def null_space(a: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the complement of vector a."""
    u, _, _ = np.linalg.svd(a.reshape(-1, 1), full_matrices=True)
    return u[:, 1:]


def sliding_state(system: System, law: ContactLaw) -> tuple[np.ndarray, float]:
    """Steady-sliding equilibrium: gravity plus the sliding friction preload mu(V) N along c_t.

    Returns (q, N) with the *sliding* normal force N, which differs from the static (friction-free) one
    whenever friction has a normal component at the contact point (tilted contact, or friction acting on
    the lower face: its moment h/2 mu N bends the beam towards or away from the disc)."""
    q0, N0 = static_state(system, law)
    mu = law.friction(law.disc_speed)
    cn, ct = system.c_n, system.c_t
    if law.method == "kinematic" and np.any(cn):
        n = system.n
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = system.K
        A[:n, n] = -(cn + mu * ct)
        A[n, :n] = cn
        sol = np.linalg.solve(A, np.concatenate([system.f, [-law.gap0]]))
        return sol[:n], float(sol[n])
    if law.method == "penalty":
        kp = law.penalty_stiffness
        Kp = system.K + kp * np.outer(cn + mu * ct, cn)
        q = np.linalg.solve(Kp, system.f - kp * law.gap0 * (cn + mu * ct))
        return q, float(-kp * (law.gap0 + cn @ q))
    return np.linalg.solve(system.K, system.f + N0 * (cn + mu * ct)), N0


@checked_arguments(normal_force=Literal["sliding", "static"])
def sliding_eigenvalues(
    system: System,
    law: ContactLaw,
    slope: float | None = None,
    *,
    mass_damping: float = 0.0,
    stiffness_damping: float = 0.0,
    normal_force: str = "sliding",
) -> np.ndarray:
    """Eigenvalues [s-1] (complex, Im >= 0 kept once) of the linearised sliding system.

    ``slope`` overrides d mu / d v_r [s mm-1] (default: the table's slope at the disc speed). The normal
    force multiplying the slope is the sliding one (``normal_force="sliding"``, friction preload included)
    or, for comparison with the old analysis, the static one (``"static"``). Rayleigh damping
    alpha M + beta K is included as in the explicit runs."""
    N0 = sliding_state(system, law)[1] if normal_force == "sliding" else static_state(system, law)[1]
    V = law.disc_speed
    mu = law.friction(V)
    dmu = law.friction.slope(V) if slope is None else slope
    M, K, cn, ct = system.M, system.K, system.c_n, system.c_t
    C = N0 * dmu * np.outer(ct, ct) + mass_damping * M + stiffness_damping * K
    if law.method == "penalty":
        K = K + law.penalty_stiffness * np.outer(cn + mu * ct, cn)
    elif law.method == "kinematic" and np.any(cn):
        Z = null_space(cn)  # admissible motions (c_n^T q = 0)
        Y = null_space(cn + mu * ct)  # test functions annihilating the multiplier's force direction
        M, C, K = Y.T @ M @ Z, Y.T @ C @ Z, Y.T @ K @ Z
    n = K.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    lam = sla.eigvals(A)
    return lam[lam.imag >= -1e-9]


def max_growth(lam: np.ndarray) -> tuple[float, float]:
    """(largest real part [s-1], its frequency [Hz])."""
    k = int(np.argmax(lam.real))
    return float(lam[k].real), float(abs(lam[k].imag) / (2 * np.pi))


def transient_growth(
    system: System,
    law: ContactLaw,
    duration: float,
    perturbation: float = 1e-3,
    *,
    mass_damping: float = 0.0,
    stiffness_damping: float = 0.0,
) -> tuple[float, float]:
    """(growth rate [s-1], frequency [Hz]) of the tangential velocity in an explicit run started from
    steady sliding with a small tangential velocity perturbation [mm s-1].

    The rate is fitted to the log of the windowed envelope while it stays below 30 % of the disc speed
    (before stick/separation limit it); the frequency is the dominant spectral peak of the tangential
    velocity over the same window, i.e. the mode that actually grows."""
    q0, _ = sliding_state(system, law)
    Minv_ct = np.linalg.solve(system.M, system.c_t)
    v0 = perturbation * Minv_ct / (system.c_t @ Minv_ct)
    r = integrate(
        system,
        law,
        duration,
        q0=q0,
        v0=v0,
        output_interval=duration / 20000,
        mass_damping=mass_damping,
        stiffness_damping=stiffness_damping,
    )
    vt = r.slip_velocity + law.disc_speed
    tc, env = window_envelope(r.t, vt, 40)
    ok = (env > 0) & (env < 0.3 * max(law.disc_speed, 1e-12))
    if ok.sum() < 8:
        return float("nan"), float("nan")
    # skip the first third of the linear range: the perturbation excites every mode, and the decaying
    # ones hide the growing one until they have died out
    t_end = tc[ok].max()
    fit = ok & (tc >= t_end / 3)
    rate = float(np.polyfit(tc[fit], np.log(env[fit]), 1)[0])
    w = (r.t >= t_end / 3) & (r.t <= t_end)
    return rate, dominant_frequency(r.t[w], vt[w])
