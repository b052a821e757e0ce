"""Complex-eigenvalue stability of steady sliding, linearised about the sliding equilibrium.

Steady sliding: beam at rest, disc surface moving at V, friction F_t = mu(V) N0 along t. With slip speed
s = V - c_t.qdot and N = N0 + dN, dF_t = mu dN - N0 mu'(V) c_t.dqdot, so

    M q'' + N0 mu' c_t c_t^T q' + K q - (c_n + mu c_t) dN = 0,

with dN = -k_p c_n^T q (penalty), dN a multiplier enforcing c_n^T q = 0 (kinematic), dN = 0 (fixed normal).
mu' < 0 is the negative damping of the falling friction law; mu c_t c_n^T is the non-symmetric
(circulatory) friction coupling that a tilted contact (angle != 0) feeds into the transverse modes.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from .explicit import ContactLaw, System, integrate, static_state
from .metrics import window_envelope


def _null(a: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the complement of vector a."""
    u, _, _ = np.linalg.svd(a.reshape(-1, 1), full_matrices=True)
    return u[:, 1:]


def sliding_eigenvalues(system: System, law: ContactLaw, slope: float | None = None) -> np.ndarray:
    """Eigenvalues [s-1] (complex, Im >= 0 kept once) of the linearised sliding system.

    ``slope`` overrides d mu / d v_r [s mm-1] (default: the table's slope at the disc speed)."""
    _, N0 = static_state(system, law)
    V = law.disc_speed
    mu = law.friction(V)
    dmu = law.friction.slope(V) if slope is None else slope
    M, K, cn, ct = system.M, system.K, system.c_n, system.c_t
    C = N0 * dmu * np.outer(ct, ct)
    if law.method == "penalty":
        K = K + law.penalty_stiffness * np.outer(cn + mu * ct, cn)
    elif law.method == "kinematic" and np.any(cn):
        Z = _null(cn)  # admissible motions (c_n^T q = 0)
        Y = _null(cn + mu * ct)  # test functions annihilating the multiplier's force direction
        M, C, K = Y.T @ M @ Z, Y.T @ C @ Z, Y.T @ K @ Z
    n = K.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    lam = sla.eigvals(A)
    return lam[lam.imag >= -1e-9]


def max_growth(lam: np.ndarray) -> tuple[float, float]:
    """(largest real part [s-1], its frequency [Hz])."""
    k = int(np.argmax(lam.real))
    return float(lam[k].real), float(abs(lam[k].imag) / (2 * np.pi))


def sliding_state(system: System, law: ContactLaw) -> np.ndarray:
    """Static state including the sliding friction preload mu(V) N0 along c_t."""
    q0, N0 = static_state(system, law)
    mu = law.friction(law.disc_speed)
    if law.method == "kinematic" and np.any(system.c_n):
        n = system.n
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = system.K
        A[:n, n] = -(system.c_n + mu * system.c_t)
        A[n, :n] = system.c_n
        return np.linalg.solve(A, np.concatenate([system.f, [-law.gap0]]))[:n]
    if law.method == "penalty":
        Kp = system.K + law.penalty_stiffness * np.outer(system.c_n + mu * system.c_t, system.c_n)
        return np.linalg.solve(Kp, system.f)
    return np.linalg.solve(system.K, system.f + N0 * (system.c_n + mu * system.c_t))


def transient_growth_rate(
    system: System, law: ContactLaw, duration: float, perturbation: float = 1e-3
) -> float:
    """Growth rate [s-1] of the tangential velocity envelope in an explicit run started from steady sliding
    with a small tangential velocity perturbation [mm s-1]; fitted while the envelope stays below 30 % of
    the disc speed (before stick/separation limits it)."""
    q0 = sliding_state(system, law)
    Minv_ct = np.linalg.solve(system.M, system.c_t)
    v0 = perturbation * Minv_ct / (system.c_t @ Minv_ct)
    r = integrate(system, law, duration, q0=q0, v0=v0, output_interval=duration / 4000)
    vt = r.slip_velocity + law.disc_speed
    tc, env = window_envelope(r.t, vt, 40)
    ok = (env > 0) & (env < 0.3 * max(law.disc_speed, 1e-12))
    if ok.sum() < 4:
        return float("nan")
    return float(np.polyfit(tc[ok], np.log(env[ok]), 1)[0])
