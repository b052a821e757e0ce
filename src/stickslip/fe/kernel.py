"""Compiled (numba) time-step kernels of the explicit central-difference integrator, one per contact law.

Same algorithm as the reference loop :func:`stickslip.fe.explicit.integrate_python` (see that module's
docstring for the contact treatment), step for step: the structure enters as the sparse CSR matrix
G = dt M^-1 K, the load increment af = dt M^-1 f and the contact vectors. Damping:

    v_{n+1/2} = c1 v_{n-1/2} + c2 (af - G (u_n + beta v_{n-1/2})),

with mass-proportional alpha in c1 = (1 - alpha dt/2)/(1 + alpha dt/2), c2 = 1/(1 + alpha dt/2) and
stiffness-proportional beta applied to the lagged half-step velocity (as explicit codes do).

Each kernel advances the steps ``n0 .. n1`` (inclusive) and records every ``every``-th step into the
output arrays from index ``j``; the Python wrapper calls it in chunks so that a progress callback can run
between chunks. Returns (next output index, last step done, diverged flag, last contact state).
"""

from __future__ import annotations

import numpy as np
from numba import njit

SEPARATED, STICK, SLIP = 0, 1, 2


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
def _structure_step(u, v, w, indptr, indices, data, af, c1, c2, beta):
    """v <- c1 v + c2 (af - G (u + beta v)), in place (w is scratch)."""
    n = u.size
    if beta != 0.0:
        for i in range(n):
            w[i] = u[i] + beta * v[i]
    else:
        for i in range(n):
            w[i] = u[i]
    for i in range(n):
        s = 0.0
        for k in range(indptr[i], indptr[i + 1]):
            s += data[k] * w[indices[k]]
        v[i] = c1 * v[i] + c2 * (af[i] - s)


@njit(cache=True)
def _record(j, t, u, v, state, Pn, Pt, dt, V, cx, cy, ci, ct, out, st, record_state, qs, vs, rec):
    out[0, j] = t
    out[1, j] = _dot(cx, u)
    out[2, j] = _dot(cy, u)
    out[3, j] = _dot(cx, v)
    out[4, j] = _dot(cy, v)
    out[5, j] = Pn / dt
    out[6, j] = Pt / dt
    out[7, j] = _sdot(ci, ct, v) - V
    st[j] = state
    if record_state:  # the DOFs listed in rec only
        for k in range(rec.size):
            qs[j, k] = u[rec[k]]
            vs[j, k] = v[rec[k]]


@njit(cache=True)
def _finish_step(
    n, every, j, n_out, u, v, dt, blowup, state, Pn, Pt, V, cx, cy, ci, ct, out, st, rs, qs, vs, rec
):
    """u <- u + dt v; record if due; returns (j, diverged)."""
    big = 0.0
    for i in range(u.size):
        u[i] += dt * v[i]
    if n % every == 0:
        if j < n_out:
            _record(j, n * dt, u, v, state, Pn, Pt, dt, V, cx, cy, ci, ct, out, st, rs, qs, vs, rec)
            j += 1
        for i in range(u.size):
            a = abs(u[i])
            if not a < blowup:  # also catches NaN
                big = 1.0
                break
    return j, big > 0.0


@njit(cache=True)
def run_kinematic(
    n0, n1, every, j, u, v, indptr, indices, data, af, c1, c2, beta,
    ci, cn, ct, cx, cy, mi, Mcn, Mct, Wnn, Wnt, Wtt, mu_s, f_speeds, f_mu, V, g0, dt, blowup,
    out, st, counts, record_state, qs, vs, rec,
):  # fmt: skip
    """Kinematic contact: exact non-penetration and exact stick by a 2x2 Delassus impulse solve."""
    det = Wnn * Wtt - Wnt * Wnt
    w = np.empty_like(u)
    n_out = st.size
    state = STICK
    n = n0
    for n in range(n0, n1 + 1):
        _structure_step(u, v, w, indptr, indices, data, af, c1, c2, beta)
        Pn = 0.0
        Pt = 0.0
        gtrial = g0 + _sdot(ci, cn, u) + dt * _sdot(ci, cn, v)
        if gtrial < 0.0:
            wt = _sdot(ci, ct, v)
            bn = -gtrial / dt
            bt = V - wt
            Pn = (Wtt * bn - Wnt * bt) / det
            Pt = (Wnn * bt - Wnt * bn) / det
            if Pn > 0.0 and abs(Pt) <= mu_s * Pn:
                state = STICK
            else:
                s = 1.0 if Pt > 0 else -1.0
                mu = np.interp(abs(wt - V), f_speeds, f_mu)
                Pn = bn / (Wnn + Wnt * s * mu)
                if Pn <= 0.0:  # friction-driven lift: normal-only correction
                    Pn = bn / Wnn
                    mu = 0.0
                Pt = s * mu * Pn
                state = SLIP
            _saxpy(mi, Mcn, Pn, v)
            _saxpy(mi, Mct, Pt, v)
        else:
            state = SEPARATED
        counts[state] += 1
        j, bad = _finish_step(
            n,
            every,
            j,
            n_out,
            u,
            v,
            dt,
            blowup,
            state,
            Pn,
            Pt,
            V,
            cx,
            cy,
            ci,
            ct,
            out,
            st,
            record_state,
            qs,
            vs,
            rec,
        )
        if bad:
            return j, n, True, state
    return j, n, False, state


@njit(cache=True)
def _tangential(v, Pn, ci, ct, mi, Mct, Wtt, mu_s, f_speeds, f_mu, V):
    """Stick/slip tangential impulse once the normal impulse Pn > 0 is applied; updates v."""
    wt = _sdot(ci, ct, v)
    Pt = (V - wt) / Wtt
    if abs(Pt) <= mu_s * Pn:
        state = STICK
    else:
        Pt = (1.0 if Pt > 0 else -1.0) * np.interp(abs(wt - V), f_speeds, f_mu) * Pn
        state = SLIP
    _saxpy(mi, Mct, Pt, v)
    return Pt, state


@njit(cache=True)
def run_penalty(
    n0, n1, every, j, u, v, indptr, indices, data, af, c1, c2, beta,
    ci, cn, ct, cx, cy, mi, Mcn, Mct, Wtt, mu_s, f_speeds, f_mu, V, g0, kp, dt, blowup,
    out, st, counts, record_state, qs, vs, rec,
):  # fmt: skip
    """Penalty contact: normal impulse kp * penetration(u_n) * dt, then the same stick/slip treatment."""
    w = np.empty_like(u)
    n_out = st.size
    state = STICK
    n = n0
    for n in range(n0, n1 + 1):
        _structure_step(u, v, w, indptr, indices, data, af, c1, c2, beta)
        Pt = 0.0
        g = g0 + _sdot(ci, cn, u)
        Pn = -kp * g * dt if g < 0.0 else 0.0
        if Pn > 0.0:
            _saxpy(mi, Mcn, Pn, v)
            Pt, state = _tangential(v, Pn, ci, ct, mi, Mct, Wtt, mu_s, f_speeds, f_mu, V)
        else:
            state = SEPARATED
        counts[state] += 1
        j, bad = _finish_step(
            n,
            every,
            j,
            n_out,
            u,
            v,
            dt,
            blowup,
            state,
            Pn,
            Pt,
            V,
            cx,
            cy,
            ci,
            ct,
            out,
            st,
            record_state,
            qs,
            vs,
            rec,
        )
        if bad:
            return j, n, True, state
    return j, n, False, state


@njit(cache=True)
def run_fixed_normal(
    n0, n1, every, j, u, v, indptr, indices, data, af, c1, c2, beta,
    ci, cn, ct, cx, cy, mi, Mcn, Mct, Wtt, mu_s, f_speeds, f_mu, V, N_fixed, dt, blowup,
    out, st, counts, record_state, qs, vs, rec,
):  # fmt: skip
    """Prescribed normal force (Section 10: no separation possible), same stick/slip treatment."""
    w = np.empty_like(u)
    n_out = st.size
    state = STICK
    n = n0
    Pn = N_fixed * dt
    for n in range(n0, n1 + 1):
        _structure_step(u, v, w, indptr, indices, data, af, c1, c2, beta)
        Pt = 0.0
        _saxpy(mi, Mcn, Pn, v)
        if Pn > 0.0:
            Pt, state = _tangential(v, Pn, ci, ct, mi, Mct, Wtt, mu_s, f_speeds, f_mu, V)
        else:
            state = SEPARATED
        counts[state] += 1
        j, bad = _finish_step(
            n,
            every,
            j,
            n_out,
            u,
            v,
            dt,
            blowup,
            state,
            Pn,
            Pt,
            V,
            cx,
            cy,
            ci,
            ct,
            out,
            st,
            record_state,
            qs,
            vs,
            rec,
        )
        if bad:
            return j, n, True, state
    return j, n, False, state
