"""Compiled explicit central-difference loops of the continuum strip on the rigid disc (numba).

One function per contact law, each advancing the state in place over a range of steps, so the caller can
run the loop in chunks (progress reports, early stop) with the same compiled code. The internal force is an
element-by-element product with the condensed element stiffnesses (a structured mesh has one distinct
element, which stays in cache), with stiffness-proportional damping f_int = K (u + beta v_{n-1/2}). Mass is
lumped: ``minv`` holds 1/m per DOF and 0 on constrained DOFs.

Contact candidates are lower-face nodes with a fixed outward disc normal n and surface-velocity direction
t = (n_y, -n_x) * direction (small displacements against a 12.5 mm disc). With a diagonal mass the Delassus
matrix of a node is diag(1/m, 1/m) in (n, t), so every node's impulses are independent and exact.

Output columns (``out[j, :]``): t, x, y, vx, vy of the output node, total normal force, total friction
force along t, slip velocity of the primary contact node. ``ost[j]``: state of the primary node
(0 separated, 1 stick, 2 slip).
"""

from __future__ import annotations

import numpy as np
from numba import njit


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
def _internal_velocity_update(dofs, kind, ke, minv, fext, u, v, w, f, beta, h):
    """v += h * M^-1 (f_ext - K (u + beta v)), K applied element by element (``ke[kind[e]]`` is element
    e's condensed 8 x 8 stiffness, ``dofs[e]`` its global DOFs); w, f: scratch."""
    nd = u.size
    if beta > 0.0:
        for i in range(nd):
            w[i] = u[i] + beta * v[i]
    else:
        w[:] = u
    f[:] = fext
    fe = np.empty(8)
    for e in range(dofs.shape[0]):
        K = ke[kind[e]]
        fe[:] = 0.0
        for b in range(8):  # column-wise with K symmetric: 8 independent sums, vectorisable as written
            ub = w[dofs[e, b]]
            for a in range(8):
                fe[a] += K[b, a] * ub
        for a in range(8):
            f[dofs[e, a]] -= fe[a]
    for i in range(nd):
        v[i] += h * minv[i] * f[i]


@njit(cache=True)
def _record(out, ost, j, time, u, v, onode, ow, fn, ft, vr, state):
    """Sample j: node 1 is sum_k ow[k] * node onode[k] (x DOF index; one node, or two straddling the axis)."""
    out[j, 0] = time
    x = y = vx = vy = 0.0
    for k in range(onode.size):
        d = onode[k]
        x += ow[k] * u[d]
        y += ow[k] * u[d + 1]
        vx += ow[k] * v[d]
        vy += ow[k] * v[d + 1]
    out[j, 1] = x
    out[j, 2] = y
    out[j, 3] = vx
    out[j, 4] = vy
    out[j, 5] = fn
    out[j, 6] = ft
    out[j, 7] = vr
    ost[j] = state


@njit(cache=True)
def run_kinematic(
    n0, n1, dt, every, dofs, kind, ke, minv, fext, beta, u, v,
    cdof, cn, ct, cg0, cm, speed, fs, fmu, primary, onode, ow, out, ost, j, counts, blowup,
):  # fmt: skip
    """Steps n0+1 .. n1 with kinematic (predictor-corrector impulse) contact. Returns (next sample index,
    1 if a displacement exceeded ``blowup`` else 0). Step 1 is the half-step start v_1/2 = v_0 + dt/2 a_0."""
    w = np.empty_like(u)
    f = np.empty_like(u)
    mu_s = fmu[0]
    nc = cdof.size
    for n in range(n0 + 1, n1 + 1):
        _internal_velocity_update(dofs, kind, ke, minv, fext, u, v, w, f, beta, 0.5 * dt if n == 1 else dt)
        fn_tot = 0.0
        ft_tot = 0.0
        state = 0
        vr = 0.0
        for c in range(nc):
            dx = cdof[c]
            dy = dx + 1
            nx, ny = cn[c, 0], cn[c, 1]
            tx, ty = ct[c, 0], ct[c, 1]
            wt = tx * v[dx] + ty * v[dy]
            st = 0
            gtrial = cg0[c] + nx * u[dx] + ny * u[dy] + dt * (nx * v[dx] + ny * v[dy])
            if gtrial < 0.0:
                m = cm[c]
                pn = -m * gtrial / dt
                pt = m * (speed - wt)
                if abs(pt) <= mu_s * pn:
                    st = 1
                else:
                    s = 1.0 if pt > 0.0 else -1.0
                    pt = s * friction_coefficient(wt - speed, fs, fmu) * pn
                    st = 2
                v[dx] += (pn * nx + pt * tx) / m
                v[dy] += (pn * ny + pt * ty) / m
                fn_tot += pn / dt
                ft_tot += pt / dt
            if c == primary:
                state = st
                vr = tx * v[dx] + ty * v[dy] - speed
        for i in range(u.size):
            u[i] += dt * v[i]
        counts[state] += 1
        if n % every == 0:
            if j < out.shape[0]:
                _record(out, ost, j, n * dt, u, v, onode, ow, fn_tot, ft_tot, vr, state)
                j += 1
            if not np.abs(u).max() < blowup:
                return j, 1
    return j, 0


@njit(cache=True)
def run_penalty(
    n0, n1, dt, every, dofs, kind, ke, minv, fext, beta, u, v,
    cdof, cn, ct, cg0, cm, speed, fs, fmu, primary, onode, ow, out, ost, j, counts, blowup, kp,
):  # fmt: skip
    """As ``run_kinematic`` with a penalty normal force kp * penetration evaluated at u_n (explicit) and the
    same exact-stick / tabulated-slip tangential impulse."""
    w = np.empty_like(u)
    f = np.empty_like(u)
    mu_s = fmu[0]
    nc = cdof.size
    for n in range(n0 + 1, n1 + 1):
        _internal_velocity_update(dofs, kind, ke, minv, fext, u, v, w, f, beta, 0.5 * dt if n == 1 else dt)
        fn_tot = 0.0
        ft_tot = 0.0
        state = 0
        vr = 0.0
        for c in range(nc):
            dx = cdof[c]
            dy = dx + 1
            nx, ny = cn[c, 0], cn[c, 1]
            tx, ty = ct[c, 0], ct[c, 1]
            st = 0
            g = cg0[c] + nx * u[dx] + ny * u[dy]
            if g < 0.0:
                m = cm[c]
                pn = -kp * g * dt
                wt = tx * v[dx] + ty * v[dy]  # n . t = 0: the normal impulse leaves wt unchanged
                pt = m * (speed - wt)
                if abs(pt) <= mu_s * pn:
                    st = 1
                else:
                    s = 1.0 if pt > 0.0 else -1.0
                    pt = s * friction_coefficient(wt - speed, fs, fmu) * pn
                    st = 2
                v[dx] += (pn * nx + pt * tx) / m
                v[dy] += (pn * ny + pt * ty) / m
                fn_tot += pn / dt
                ft_tot += pt / dt
            if c == primary:
                state = st
                vr = tx * v[dx] + ty * v[dy] - speed
        for i in range(u.size):
            u[i] += dt * v[i]
        counts[state] += 1
        if n % every == 0:
            if j < out.shape[0]:
                _record(out, ost, j, n * dt, u, v, onode, ow, fn_tot, ft_tot, vr, state)
                j += 1
            if not np.abs(u).max() < blowup:
                return j, 1
    return j, 0
