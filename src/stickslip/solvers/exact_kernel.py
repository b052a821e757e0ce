"""The exact event-driven solver's phase loop and sampling, compiled (numba).

The same algorithm as the pure-Python reference :class:`stickslip.solvers.exact.ExactSwitchSolver` on
``events.EventDrivenSolver``, operation for operation: stick in closed form (the release time a root of a
quadratic, ``first_exit_root``), slip as the closed-form ``linear.LinearSegment``, the return to v_r = 0
bracketed on the same grid (same spacing, the same doubling windows) and refined by Brent's method with the
same tolerances (a port of scipy.optimize.brentq's C loop, BSD licence), grazing caught at the same local
minima of the gap with the same curvature bound, the belt's stop as a scheduled event, the same segment budget
and zero-length guard. Only the elementary functions differ (libm's exp/sin/cos here, numpy's there: an ulp
apart), so segment ends agree with the reference to the root-search tolerance, not bit for bit
(``tests/solvers/test_exact_compiled.py``).

The model arrives as plain numbers (``run`` below); nothing here knows a Python model object. Every jitted
function lives in this one module: numba's on-disk cache (``cache=True``) of a function is invalidated only
by edits to that function's own file.

Segment table (``run``'s first result), one row per segment, ``SEG_COLUMNS``:
t0, t1, phase, x0, v0, c, g0, g1 -- a slip row is ``LinearSegment(m, c, k, g0, g1, x0, v0)`` from t0; a stick
row (phase 0) is ``StickMotion(x0, vb0 = v0, slope = g1)`` (c, g0 unused, 0).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

SEG_COLUMNS = ("t0", "t1", "phase", "x0", "v0", "c", "g0", "g1")
SLIP_BACKWARD, STICK, SLIP_FORWARD = -1, 0, 1
CONTACT = 2  # v_r = 0: the next mode is decided there (the reference's 'contact')
NO_RELEASE = 3

# status codes of ``run`` (the Python side turns them into the reference's exceptions)
OK = 0
TOO_MANY_SEGMENTS = 1  # SolverError: more than max_segments segments
ZERO_LENGTH = 2  # SolverError: max_zero_length zero-length segments in a row
ROOT_NAN = 3  # ValueError of scipy's brentq: the function value is NaN
ROOT_SIGN = 4  # ValueError of scipy's brentq: f(a) and f(b) must have different signs
ROOT_CONVERGENCE = 5  # RuntimeError of scipy's brentq: no convergence in 100 iterations

BRENT_XTOL = 1e-15
# written here, not imported from .exact: numba's cache is keyed on this file, so an imported constant
# would go stale in a cached kernel (tests/solvers/test_exact_compiled.py checks the two are equal)
PLATEAU_BAND = 1e-9  # ExactSwitchSolver's PLATEAU_BAND (the reference's, and why)
BRENT_RTOL = 4 * np.finfo(float).eps
BRENT_MAXITER = 100

# model / settings vector indices (``run``'s ``par``)
P_M, P_C, P_K, P_A, P_B, P_KAPPA, P_VP, P_ASTICK, P_X0, P_V0, P_VB, P_DECEL, P_STOP = range(13)

# slip segment record (a tuple of floats, built by ``_slip_setup``)
# (m, c, k, g0, g1, p0, p1, alpha, w2, w, h0, h1, q, vs, s, vb0, slope, vp, outside, plateau)


@njit(cache=True)
def _pymax2(a, b):
    """Python's max(a, b): a unless b > a."""
    return b if b > a else a


@njit(cache=True)
def _pymin2(a, b):
    """Python's min(a, b): a unless b < a."""
    return b if b < a else a


@njit(cache=True)
def _nanmin(a, b):
    """np.minimum of two floats (NaN propagates)."""
    if a != a:
        return a
    if b != b:
        return b
    return b if b < a else a


@njit(cache=True)
def belt_velocity(par, t):
    vb = par[P_VB] - par[P_DECEL] * t
    return vb if vb > 0.0 else (0.0 if vb <= 0.0 else vb)


@njit(cache=True)
def belt_acceleration(par, t):
    return -par[P_DECEL] if t < par[P_STOP] else 0.0


@njit(cache=True)
def stick_demand(par, t, x):
    """BeltModel.stick_demand with the stick-limit model's coefficients (b, kappa are the model's)."""
    vb = belt_velocity(par, t)
    needed = par[P_M] * belt_acceleration(par, t) + par[P_C] * vb + par[P_K] * x
    return needed - (par[P_B] + par[P_KAPPA]) * vb


@njit(cache=True)
def first_exit_root(c0, c1, c2):
    """exact.first_exit_root: first tau >= 0 where c0 + c1 tau + c2 tau^2 (<= 0 at 0) turns positive."""
    r1 = math.nan
    r2 = math.nan
    n = 0
    if c2 == 0.0:
        if c1 != 0.0:
            r1 = -c0 / c1
            n = 1
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc >= 0.0:
            sq = math.sqrt(disc)
            q = -0.5 * (c1 + math.copysign(sq, c1)) if c1 != 0.0 else -0.5 * sq
            r1 = q / c2
            n = 1
            if q != 0.0:
                r2 = c0 / q
                n = 2
    best = math.inf
    found = False
    for i in range(n):
        r = r1 if i == 0 else r2
        if abs(r) <= 1e-300:
            r = _pymax2(r, 0.0)
        if r < 0.0:
            continue
        slope = c1 + 2.0 * c2 * r
        if slope > 0.0 or (slope == 0.0 and c2 > 0.0):
            if not found or r < best:
                best = r
                found = True
    if c0 == 0.0 and (c1 > 0.0 or (c1 == 0.0 and c2 > 0.0)):
        if not found or 0.0 < best:
            best = 0.0
            found = True
    return best if found else math.inf


@njit(cache=True)
def contact_decision(par, t, x):
    """Stick or the slip direction at v_r = 0 (ExactSwitchSolver._contact_decision, stick-limit a)."""
    a = par[P_ASTICK]
    d = stick_demand(par, t, x)
    if a < 0:
        if d > -a:
            return SLIP_BACKWARD
        if d < a:
            return SLIP_FORWARD
        return STICK
    if -a - d > 0:
        return SLIP_FORWARD
    if a - d < 0:
        return SLIP_BACKWARD
    return SLIP_BACKWARD if d > 0 else SLIP_FORWARD


@njit(cache=True)
def mode_from_state(par, t, v):
    vr = v - belt_velocity(par, t)
    if vr > 0:
        return SLIP_FORWARD
    if vr < 0:
        return SLIP_BACKWARD
    return CONTACT


# ------------------------------------------------------------------------------- closed-form slip motion
@njit(cache=True)
def linear_coefficients(m, c, k, g0, g1, x0, v0):
    """LinearSegment.__post_init__: (p0, p1, alpha, w2, w, h0, h1, q, vs)."""
    p1 = g1 / k
    p0 = (g0 - c * p1) / k
    alpha = -c / (2.0 * m)
    w2 = k / m - alpha * alpha
    w = math.sqrt(abs(w2))
    h0 = x0 - p0
    h1 = v0 - p1
    q = h1 - alpha * h0
    vs = -w2 * h0
    return p0, p1, alpha, w2, w, h0, h1, q, vs


@njit(cache=True)
def linear_state(p0, p1, alpha, w2, w, h0, q, vs, tau):
    """LinearSegment.state at one local time: (x, v)."""
    if w2 > 0.0:
        e = math.exp(alpha * tau)
        ec = e * math.cos(w * tau)
        es = e * math.sin(w * tau) / w
    elif w2 < 0.0:
        e_plus = math.exp((alpha + w) * tau)
        e_minus = math.exp((alpha - w) * tau)
        ec = 0.5 * (e_plus + e_minus)
        es = e_plus * (-math.expm1(-2.0 * w * tau)) / (2.0 * w)
    else:
        e = math.exp(alpha * tau)
        ec = e
        es = e * tau
    xh = h0 * ec + q * es
    vh = alpha * xh + vs * es + q * ec
    return p0 + p1 * tau + xh, p1 + vh


@njit(cache=True)
def _slip_setup(m, c, k, g0, g1, x0, v0, s, vb0, slope, vp, outside, plateau):
    p0, p1, alpha, w2, w, h0, h1, q, vs = linear_coefficients(m, c, k, g0, g1, x0, v0)
    return (m, c, k, g0, g1, p0, p1, alpha, w2, w, h0, h1, q, vs, s, vb0, slope, vp, outside, plateau)


@njit(cache=True)
def _velocity(S, tau):
    return linear_state(S[5], S[6], S[7], S[8], S[9], S[10], S[12], S[13], tau)


@njit(cache=True)
def gap(S, tau):
    """The slip's gap (ExactSwitchSolver._slip's ``gap``): positive while the slip lasts."""
    s, vb0, slope, vp = S[14], S[15], S[16], S[17]
    v = _velocity(S, tau)[1]
    g = s * (v - (vb0 + slope * tau))
    if S[18] != 0.0:  # outside the plateau: s v_r - v_p
        return g - vp
    if S[19] != 0.0:
        return _nanmin(g, vp - g)
    return g


@njit(cache=True)
def gap_rate(S, tau):
    """d gap / d tau (``gap_rate``)."""
    m, c, k, g0, g1 = S[0], S[1], S[2], S[3], S[4]
    s, vb0, slope, vp = S[14], S[15], S[16], S[17]
    x, v = _velocity(S, tau)
    acc = (g0 + g1 * tau - c * v - k * x) / m
    rate = s * (acc - slope)
    if S[19] == 0.0 or S[18] != 0.0:
        return rate
    g = s * (v - (vb0 + slope * tau))
    return rate if g <= vp - g else -rate


@njit(cache=True)
def _f(which, S, tau):
    return gap(S, tau) if which == 0 else gap_rate(S, tau)


@njit(cache=True)
def brentq(which, S, xa, xb):
    """scipy.optimize.brentq(f, xa, xb, xtol=1e-15, rtol=4 eps) on ``gap`` (which = 0) or ``gap_rate`` (1):
    (root, status, x of a NaN value). The same iteration as scipy's C loop (brentq.c, BSD)."""
    xtol, rtol = BRENT_XTOL, BRENT_RTOL
    xpre, xcur = xa, xb
    xblk, fblk, spre, scur = 0.0, 0.0, 0.0, 0.0
    fpre = _f(which, S, xpre)
    if fpre != fpre:
        return 0.0, ROOT_NAN, xpre
    fcur = _f(which, S, xcur)
    if fcur != fcur:
        return 0.0, ROOT_NAN, xcur
    if fpre * fcur > 0:
        return 0.0, ROOT_SIGN, 0.0
    if fpre == 0:
        return xpre, OK, 0.0
    if fcur == 0:
        return xcur, OK, 0.0
    for _ in range(BRENT_MAXITER):
        if fpre * fcur < 0:
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre = xcur
            xcur = xblk
            xblk = xpre
            fpre = fcur
            fcur = fblk
            fblk = fpre
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur, OK, 0.0
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
                spre = scur
                scur = stry
            else:
                spre = sbis
                scur = sbis
        else:
            spre = sbis
            scur = sbis
        xpre = xcur
        fpre = fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0 else -delta
        fcur = _f(which, S, xcur)
        if fcur != fcur:
            return 0.0, ROOT_NAN, xcur
    return xcur, ROOT_CONVERGENCE, xcur


@njit(cache=True)
def curvature_bound(S, lo, hi):
    """LinearSegment.velocity_curvature_bound on [lo, hi]."""
    m, k, alpha, w2, h0, h1 = S[0], S[2], S[7], S[8], S[10], S[11]
    b = alpha * (h1 - alpha * h0) - w2 * h0
    if w2 > 0.0:
        w = math.sqrt(w2)
        env = math.exp(alpha * (lo if alpha < 0.0 else hi))
        return (k / m) * math.hypot(h1, b / w) * env
    if w2 < 0.0:
        w = math.sqrt(-w2)
        c1, c2 = 0.5 * (h1 + b / w), 0.5 * (h1 - b / w)
        l1, l2 = alpha + w, alpha - w
        e1 = math.exp(l1 * (lo if l1 < 0.0 else hi))
        e2 = math.exp(l2 * (lo if l2 < 0.0 else hi))
        return l1 * l1 * abs(c1) * e1 + l2 * l2 * abs(c2) * e2
    return math.inf


@njit(cache=True)
def free_velocity_envelope(S, tau_from):
    """LinearSegment.free_velocity_envelope."""
    alpha, w2, h0, h1 = S[7], S[8], S[10], S[11]
    b = alpha * (h1 - alpha * h0) - w2 * h0
    if w2 > 0.0 and alpha <= 0.0:
        return math.hypot(h1, b / math.sqrt(w2)) * math.exp(alpha * tau_from)
    if w2 < 0.0:
        w = math.sqrt(-w2)
        if alpha + w <= 0.0:
            c1, c2 = 0.5 * (h1 + b / w), 0.5 * (h1 - b / w)
            decay1, decay2 = math.exp((alpha + w) * tau_from), math.exp((alpha - w) * tau_from)
            return abs(c1) * decay1 + abs(c2) * decay2
    return math.inf


@njit(cache=True)
def clear_to_the_end(S, tau_from, tol):
    """ExactSwitchSolver._clear_to_the_end."""
    s, vb0, slope, vp = S[14], S[15], S[16], S[17]
    if slope != 0.0:
        return False
    spread = free_velocity_envelope(S, tau_from)
    if not math.isfinite(spread):
        return False
    centre = s * (S[6] - vb0)
    if S[18] != 0.0:
        return centre - vp - spread > tol
    if not math.isfinite(vp):
        return centre - spread > tol
    return centre - spread > tol and vp - (centre + spread) > tol


@njit(cache=True)
def first_event(S, taus, gaps, n, tol):
    """ExactSwitchSolver._first_event on taus[:n], gaps[:n]: (found, tau, status, nan_x)."""
    first_cross = n
    for i in range(1, n):
        if gaps[i] <= 0.0:
            first_cross = i
            break
    for k in range(1, min(first_cross, n - 1)):
        if not (gaps[k] <= gaps[k - 1] and gaps[k] <= gaps[k + 1]):
            continue
        lo, hi = taus[k - 1], taus[k + 1]
        if gaps[k] - curvature_bound(S, lo, hi) * (hi - lo) ** 2 / 2 > tol:
            continue  # provably clear of zero (NaN: not clear)
        r_lo, r_hi = gap_rate(S, lo), gap_rate(S, hi)
        if r_lo < 0.0 < r_hi:
            tau_min, status, nan_x = brentq(1, S, lo, hi)
            if status != OK:
                return True, tau_min, status, nan_x
        else:
            tau_min = taus[k]
        g_min = gap(S, tau_min)
        if g_min < -tol:  # a crossing the grid stepped over
            root, status, nan_x = brentq(0, S, taus[k - 1], tau_min)
            return True, root, status, nan_x
        if g_min <= tol:
            return True, tau_min, OK, 0.0
    if first_cross < n:
        lo, hi = taus[first_cross - 1], taus[first_cross]
        if gaps[first_cross] == 0.0:
            return True, hi, OK, 0.0
        root, status, nan_x = brentq(0, S, lo, hi)
        return True, root, status, nan_x
    return False, 0.0, OK, 0.0


@njit(cache=True)
def slip(par, t0, x0, v0, s, t_limit, spp, graze, window0, window1):
    """One slip phase (ExactSwitchSolver._slip): (t1, hit, c, g0, g1, status, nan_x)."""
    m, cd, k = par[P_M], par[P_C], par[P_K]
    a, b, kappa, vp = par[P_A], par[P_B], par[P_KAPPA], par[P_VP]
    plateau = math.isfinite(vp)
    vb0 = belt_velocity(par, t0)
    slope = belt_acceleration(par, t0)
    sf = float(s)
    outside = False
    if plateau:
        rel = sf * (v0 - vb0)
        if rel > vp * (1 + PLATEAU_BAND):
            outside = True
        elif rel >= vp * (1 - PLATEAU_BAND):
            force = a * sf + b * sf * vp
            kv = b + kappa
            acc = (force + kv * vb0 - cd * v0 - k * x0) / m
            outside = sf * (acc - slope) > 0
    if outside:
        kv = b + kappa
        c = cd - 0.0
        g0 = (a * sf + b * sf * vp) + kv * vb0
        g1 = kv * slope
    else:
        c = cd - b
        g0 = a * sf + kappa * vb0
        g1 = kappa * slope
    S = _slip_setup(
        m, c, k, g0, g1, x0, v0, sf, vb0, slope, vp, 1.0 if outside else 0.0, 1.0 if plateau else 0.0
    )
    alpha = S[7]

    tau_max = t_limit - t0
    vscale = _pymax2(_pymax2(_pymax2(abs(vb0), abs(a) / math.sqrt(k * m)), abs(v0)), 1e-300)
    tol = graze * vscale
    timescale = 2.0 * math.pi * math.sqrt(m / k)
    if alpha != 0.0:
        timescale = _pymin2(timescale, 2.0 * math.pi / abs(alpha))
    h = timescale / spp

    # a slip that starts at v_r = 0 leaves it with zero gap: find a first positive sample
    start = _pymin2(h, tau_max)
    while gap(S, start) <= 0.0 and start > 1e-13 * h:
        start *= 0.125
    if gap(S, start) <= 0.0:
        return _finish(S, t0, 0.0, c, g0, g1, OK, 0.0)
    lo_tau, lo_gap = 0.0, 0.0
    tau_k = start
    window = window0
    taus = np.empty(window + 1)
    gaps = np.empty(window + 1)
    while True:
        if taus.shape[0] < window + 1:
            taus = np.empty(window + 1)
            gaps = np.empty(window + 1)
        taus[0], gaps[0] = lo_tau, lo_gap
        n = 0
        for i in range(window):
            g = tau_k + h * float(i)
            if not g < tau_max:
                break
            n += 1
            taus[n] = g
        if n < window:
            n += 1
            taus[n] = tau_max
        for i in range(1, n + 1):
            gaps[i] = gap(S, taus[i])
        found, tau_hit, status, nan_x = first_event(S, taus, gaps, n + 1, tol)
        if found:
            return _finish(S, t0, tau_hit, c, g0, g1, status, nan_x)
        if taus[n] >= tau_max or clear_to_the_end(S, taus[n], tol):
            return t_limit, False, c, g0, g1, OK, 0.0
        lo_tau, lo_gap = taus[n - 1], gaps[n - 1]
        tau_k = taus[n]
        window = min(2 * window, window1)


@njit(cache=True)
def _finish(S, t0, tau_hit, c, g0, g1, status, nan_x):
    if S[19] == 0.0:
        return t0 + tau_hit, True, c, g0, g1, status, nan_x
    rel = S[14] * (_velocity(S, tau_hit)[1] - (S[15] + S[16] * tau_hit))
    hit = S[18] == 0.0 and rel < 0.5 * S[17]
    return t0 + tau_hit, hit, c, g0, g1, status, nan_x


@njit(cache=True)
def stick(par, t0, x0, t_limit):
    """One stick phase (ExactSwitchSolver._stick): (t1, release mode or NO_RELEASE, vb0, slope)."""
    a_abs = abs(par[P_ASTICK])
    vb0 = belt_velocity(par, t0)
    slope = belt_acceleration(par, t0)
    d0 = stick_demand(par, t0, x0)
    smooth = par[P_C] - par[P_B] - par[P_KAPPA]
    d1 = smooth * slope + par[P_K] * vb0
    d2 = 0.5 * par[P_K] * slope
    up = first_exit_root(d0 - a_abs, d1, d2)
    down = first_exit_root(-a_abs - d0, -d1, -d2)
    tau = _pymin2(up, down)
    if t0 + tau >= t_limit:
        return t_limit, NO_RELEASE, vb0, slope
    release = SLIP_BACKWARD if up <= down else SLIP_FORWARD
    return t0 + tau, release, vb0, slope


@njit(cache=True)
def run(par, t_end, spp, graze, max_segments, max_zero_length, window0, window1):
    """The phase loop (EventDrivenSolver._integrate) up to t_end.

    Returns (segment table, n segments, steps, events, status, info_t, info_x, info_n, nan_x)."""
    stop = par[P_STOP]
    t, x, v = 0.0, par[P_X0], par[P_V0]
    cap = 64
    segs = np.zeros((cap, 8))
    nseg = 0
    steps = 0
    events = 0
    zero_run = 0
    mode = mode_from_state(par, t, v)
    while t < t_end:
        if nseg >= max_segments:
            return segs, nseg, steps, events, TOO_MANY_SEGMENTS, t, x, 0, 0.0
        if mode == CONTACT:
            mode = contact_decision(par, t, x)
            events += 1
            continue
        t_limit = (stop if stop < t_end else t_end) if t < stop else t_end
        if nseg == cap:
            cap *= 2
            grown = np.zeros((cap, 8))
            grown[:nseg] = segs[:nseg]
            segs = grown
        row = segs[nseg]
        if mode == STICK:
            t1, release, vb0, slope = stick(par, t, x, t_limit)
            next_mode = CONTACT if release == NO_RELEASE else release
            row[0], row[1], row[2] = t, t1, STICK
            row[3], row[4], row[5], row[6], row[7] = x, vb0, 0.0, 0.0, slope
            tau = t1 - t
            x1 = x + vb0 * tau + 0.5 * slope * tau * tau
            v1 = vb0 + slope * tau + 0 * tau
        else:
            t1, hit, c, g0, g1, status, nan_x = slip(
                par, t, x, v, mode, t_limit, spp, graze, window0, window1
            )
            if status != OK:  # the reference raises inside its root search: nothing of this phase counts
                return segs, nseg, steps, events, status, t, x, 0, nan_x
            next_mode = CONTACT if hit else mode
            row[0], row[1], row[2] = t, t1, mode
            row[3], row[4], row[5], row[6], row[7] = x, v, c, g0, g1
            p0, p1, alpha, w2, w, h0, h1, q, vs = linear_coefficients(par[P_M], c, par[P_K], g0, g1, x, v)
            x1, v1 = linear_state(p0, p1, alpha, w2, w, h0, q, vs, t1 - t)
        steps += 1
        nseg += 1
        t0 = t
        zero_run = zero_run + 1 if t1 - t0 <= 1e-14 * _pymax2(1.0, abs(t0)) else 0
        if zero_run > max_zero_length:
            return segs, nseg, steps, events, ZERO_LENGTH, t, x, zero_run, 0.0
        t = t1
        x, v = x1, v1
        if next_mode == CONTACT or mode == STICK:
            v = belt_velocity(par, t)
        if next_mode != CONTACT and t >= stop and t0 < stop:
            next_mode = mode_from_state(par, t, v)
        mode = next_mode
    return segs, nseg, steps, events, OK, t, x, 0, 0.0


@njit(cache=True)
def sample(segs, nseg, m, k, t_eval):
    """events.sample_segments on the segment table: (x, v, phase); NaN past the last segment."""
    n = t_eval.shape[0]
    x = np.full(n, np.nan)
    v = np.full(n, np.nan)
    phase = np.zeros(n, dtype=np.int8)
    for j in range(nseg):
        t0, t1 = segs[j, 0], segs[j, 1]
        lo = np.searchsorted(t_eval, t0, side="left")
        if j == nseg - 1:
            hi = np.searchsorted(t_eval, t1, side="right")
        else:
            hi = np.searchsorted(t_eval, t1, side="left")
        if hi <= lo:
            continue
        ph = int(segs[j, 2])
        x0, v0, c, g0, g1 = segs[j, 3], segs[j, 4], segs[j, 5], segs[j, 6], segs[j, 7]
        if ph == STICK:
            for i in range(lo, hi):
                tau = t_eval[i] - t0
                x[i] = x0 + v0 * tau + 0.5 * g1 * tau * tau
                v[i] = v0 + g1 * tau + 0 * tau
                phase[i] = STICK
        else:
            p0, p1, alpha, w2, w, h0, h1, q, vs = linear_coefficients(m, c, k, g0, g1, x0, v0)
            for i in range(lo, hi):
                x[i], v[i] = linear_state(p0, p1, alpha, w2, w, h0, q, vs, t_eval[i] - t0)
                phase[i] = ph
    return x, v, phase
