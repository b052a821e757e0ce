"""Closed-form solution of M y'' + c y' + k y = g0 + g1 tau (one slip segment, all damping cases)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LinearSegment:
    """Solution from state (x0, v0) at local time tau = 0; valid for any sign of c, including c = 0.

    The homogeneous part is written as e^{alpha tau}[h0 C(tau) + (h1 - alpha h0) S(tau)] with
    C = cos(w tau), S = sin(w tau)/w (w^2 = k/m - alpha^2), continued to cosh/sinh and to (1, tau), so
    critical damping needs no special case and nothing cancels catastrophically.
    """

    m: float
    c: float
    k: float
    g0: float
    g1: float
    x0: float
    v0: float

    def __post_init__(self):
        p1 = self.g1 / self.k
        p0 = (self.g0 - self.c * p1) / self.k
        alpha = -self.c / (2.0 * self.m)
        object.__setattr__(self, "_p", (p0, p1))
        object.__setattr__(self, "_alpha", alpha)
        w2 = self.k / self.m - alpha * alpha
        object.__setattr__(self, "_w2", w2)
        object.__setattr__(self, "_w", float(np.sqrt(abs(w2))))  # the (hyperbolic) frequency, computed once
        h0, h1 = self.x0 - p0, self.v0 - p1
        object.__setattr__(self, "_h", (h0, h1))
        # coefficients of the kernels in x_h and v_h, computed once (state() is the exact solver's inner loop)
        object.__setattr__(self, "_q", h1 - alpha * h0)
        object.__setattr__(self, "_vs", -w2 * h0)

    def _kernels(self, tau):
        """e^{alpha tau} C(tau) and e^{alpha tau} S(tau)."""
        alpha, w2, w = self._alpha, self._w2, self._w
        if w2 > 0.0:
            e = np.exp(alpha * tau)
            return e * np.cos(w * tau), e * np.sin(w * tau) / w
        if w2 < 0.0:
            e_plus = np.exp((alpha + w) * tau)
            e_minus = np.exp((alpha - w) * tau)
            return 0.5 * (e_plus + e_minus), e_plus * (-np.expm1(-2.0 * w * tau)) / (2.0 * w)
        e = np.exp(alpha * tau)
        return e, e * tau

    def state(self, tau):
        """(x, v) at local times tau (scalar or array).

        A scalar stays a Python float: numpy's functions give the same bits on it as on a 0-d array at a
        quarter of the cost, and the root searches of the exact solver call this a million times a build."""
        if isinstance(tau, (float, int, np.floating)):
            tau = float(tau)
            # numpy's exp/cos/sin (the array path's functions, so both give the same bits), then Python
            # float arithmetic: the same IEEE operations in the same order as on numpy scalars, at a third of
            # the cost per operation
            ec, es = (float(k) for k in self._kernels(tau))
        else:
            tau = np.asarray(tau, dtype=float)
            ec, es = self._kernels(tau)
        h0, q = self._h[0], self._q
        xh = h0 * ec + q * es
        vh = self._alpha * xh + self._vs * es + q * ec
        p0, p1 = self._p
        return p0 + p1 * tau + xh, p1 + vh

    def velocity_curvature_bound(self, tau_lo, tau_hi):
        """An upper bound of |d^2 v / d tau^2| on [tau_lo, tau_hi] (arrays allowed); inf at critical damping.

        The particular part of v is linear in tau, so only the free part counts. Underdamped, it is
        e^{alpha tau} (A cos w tau + B sin w tau), a phasor turning at alpha + i w:
        |v''| <= (k/m) R e^{alpha tau} with R = hypot(A, B). Overdamped, it is c1 e^{l1 tau} + c2 e^{l2 tau}:
        |v''| <= sum l^2 |c| e^{l tau}.
        The exact solver uses the bound to skip the root search at sampled minima of the slip velocity that
        provably stay clear of zero."""
        alpha, w2 = self._alpha, self._w2
        h0, h1 = self._h
        b = alpha * (h1 - alpha * h0) - w2 * h0  # v_h = e^{alpha tau} (h1 C(tau) + b S(tau))
        lo, hi = np.asarray(tau_lo, dtype=float), np.asarray(tau_hi, dtype=float)

        def envelope(rate):  # max of e^{rate tau} on [lo, hi]
            return np.exp(rate * (lo if rate < 0.0 else hi))

        with np.errstate(over="ignore", invalid="ignore"):
            if w2 > 0.0:
                w = np.sqrt(w2)
                return (self.k / self.m) * np.hypot(h1, b / w) * envelope(alpha)
            if w2 < 0.0:
                w = np.sqrt(-w2)
                c1, c2 = 0.5 * (h1 + b / w), 0.5 * (h1 - b / w)
                l1, l2 = alpha + w, alpha - w
                return l1 * l1 * abs(c1) * envelope(l1) + l2 * l2 * abs(c2) * envelope(l2)
        return np.full(np.shape(lo), np.inf)

    def free_velocity_envelope(self, tau_from: float) -> float:
        """A bound of |v - v_particular| for every tau >= tau_from (inf if the free motion can grow).

        Underdamped |v_h| <= R e^{alpha tau}; overdamped |v_h| <= |c1| e^{l1 tau} + |c2| e^{l2 tau}; both
        non-increasing when every rate is <= 0. The exact solver uses it to end a slip that provably never
        returns to v_r = 0 without sampling the rest of the interval."""
        alpha, w2 = self._alpha, self._w2
        h0, h1 = self._h
        b = alpha * (h1 - alpha * h0) - w2 * h0
        if w2 > 0.0 and alpha <= 0.0:
            return float(np.hypot(h1, b / np.sqrt(w2)) * np.exp(alpha * tau_from))
        if w2 < 0.0:
            w = np.sqrt(-w2)
            if alpha + w <= 0.0:
                c1, c2 = 0.5 * (h1 + b / w), 0.5 * (h1 - b / w)
                decay1, decay2 = np.exp((alpha + w) * tau_from), np.exp((alpha - w) * tau_from)
                return float(abs(c1) * decay1 + abs(c2) * decay2)
        return np.inf

    @property
    def particular_velocity(self) -> float:
        """dv/dtau of the particular solution p0 + p1 tau (constant)."""
        return self._p[1]

    def acceleration(self, tau):
        x, v = self.state(tau)
        return (self.g0 + self.g1 * np.asarray(tau, dtype=float) - self.c * v - self.k * x) / self.m
