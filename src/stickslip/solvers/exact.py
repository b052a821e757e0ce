"""Exact event-driven (switch model) solver for the affine friction laws.

Stick: the mass moves with the belt while the friction it needs stays inside the static limit
(|D| <= |a|, see ``BeltModel.stick_demand``); D is quadratic in time during stick, so the release time is a
closed-form root. Slip: a linear ODE with constant coefficients (``LinearSegment``); the return to
v_r = 0 is bracketed on a grid of the closed form and refined with Brent's method to machine precision.
Tangential returns (grazing) are caught at the local minima of |v_r|, so an orbit that touches the belt
velocity without crossing it is not missed. The belt's stop (decelerating scene) is a scheduled event.

This module is the pure-Python statement of the algorithm and the tests' reference. The pipeline's method
``exact`` runs the same algorithm compiled: ``exact_compiled.CompiledExactSolver`` (``exact_kernel``), which
agrees with this one to the root search's tolerance (``tests/solvers/test_exact_compiled.py``); an edit to
the algorithm here must be made there too.
"""

from __future__ import annotations

import math

import numpy as np

from ..model.equations import BeltModel
from ..model.params import Count, Positive, parameter_set
from .base import SLIP_BACKWARD, SLIP_FORWARD, STICK
from .events import EventDrivenSolver, Segment, StickMotion, sample_segments
from .linear import LinearSegment

__all__ = [
    "ExactSwitchSolver",
    "Segment",
    "StickMotion",
    "first_exit_root",
    "sample_segments",
    "stick_or_slip",
    "stick_segment",
]

#: Samples of the slip gap per scanning window: the first window, and the largest it doubles up to.
WINDOW_SAMPLES = (256, 1 << 16)
#: A slip that starts with |v_r| within this fraction of the plateau speed starts on the plateau surface and
#: leaves it where the outer law's acceleration points. An event on the surface leaves the state off it by
#: the closed form's rounding, eps times its terms: 1e-12 of v_p was too narrow (a state 1-2e-12 on the side
#: it was leaving started zero-length segments there until the run failed: 56 of 30000 random runs).
PLATEAU_BAND = 1e-9


def first_exit_root(c0: float, c1: float, c2: float) -> float:
    """First tau >= 0 at which g = c0 + c1 tau + c2 tau^2 (g(0) <= 0) becomes positive; inf if never."""
    candidates = []
    if c2 == 0.0:
        if c1 != 0.0:
            candidates.append(-c0 / c1)
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc >= 0.0:
            sq = math.sqrt(disc)
            q = -0.5 * (c1 + math.copysign(sq, c1)) if c1 != 0.0 else -0.5 * sq
            roots = [q / c2] if q == 0.0 else [q / c2, c0 / q]
            candidates.extend(roots)
    exits = []
    for r in candidates:
        r = max(r, 0.0) if abs(r) <= 1e-300 else r
        if r < 0.0:
            continue
        slope = c1 + 2.0 * c2 * r
        if slope > 0.0 or (slope == 0.0 and c2 > 0.0):
            exits.append(r)
    if c0 == 0.0 and (c1 > 0.0 or (c1 == 0.0 and c2 > 0.0)):
        exits.append(0.0)
    return min(exits) if exits else math.inf


def stick_or_slip(demand: float, limit: float) -> int:
    """At v_r = 0 under friction that holds the mass (static limit ``limit`` [N]): stick while |D| <= limit,
    else slip the way the demand D pushes (D > limit: backward)."""
    if demand > limit:
        return SLIP_BACKWARD
    if demand < -limit:
        return SLIP_FORWARD
    return STICK


def stick_segment(params, t0: float, x0: float, t_limit: float, d0: float, smooth: float, limit: float):
    """The stick from (t0, x0), the mass on the belt: the demand D (d0 at t0; its part linear in the belt
    speed has the coefficient ``smooth``) is quadratic in time, and the stick lasts while |D| <= ``limit``.
    Returns (its Segment up to the release or ``t_limit``, the release's slip direction or None)."""
    vb0 = float(params.belt_velocity_at(t0))
    slope = float(params.belt_acceleration_at(t0))
    d1 = smooth * slope + params.stiffness * vb0
    d2 = 0.5 * params.stiffness * slope
    up = first_exit_root(d0 - limit, d1, d2)
    down = first_exit_root(-limit - d0, -d1, -d2)
    tau = min(up, down)
    motion = StickMotion(x0, vb0, slope)
    if t0 + tau >= t_limit:
        return Segment(t0, t_limit, STICK, motion), None
    return Segment(t0, t0 + tau, STICK, motion), SLIP_BACKWARD if up <= down else SLIP_FORWARD


@parameter_set(frozen=False)
class ExactSwitchSolver(EventDrivenSolver):
    """The exact solver in pure Python, the reference of the compiled ``CompiledExactSolver`` (the method
    ``exact``); ``graze_tolerance`` is relative to the model's velocity scale."""

    samples_per_period: Count = 64
    graze_tolerance: Positive = 1e-12
    max_segments: Count = 200_000
    max_zero_length: Count = 50
    name: str = "exact"

    SETTING_NAMES = ("samples_per_period", "graze_tolerance")

    def _phase(self, model, mode, t, x, v, t_limit, stats):
        if mode == STICK:
            seg, release = self._stick(model, t, x, t_limit)
            next_mode = release if release is not None else "contact"
        else:
            seg, hit = self._slip(model, t, x, v, mode, t_limit)
            next_mode = "contact" if hit else mode
        stats.steps += 1
        return seg, next_mode

    # -- pieces ---------------------------------------------------------------------------------------
    @staticmethod
    def _contact_decision(model: BeltModel, t: float, x: float):
        """Stick or the slip direction at v_r = 0 (Filippov's rule; sgn(0) = 0 where v_r = 0 repels)."""
        a = model.friction.a
        d = float(model.stick_demand(t, x))
        if a < 0:  # attracting: stick while the demand fits the static limit
            return stick_or_slip(d, -a)
        if -a - d > 0:
            return SLIP_FORWARD
        if a - d < 0:
            return SLIP_BACKWARD
        return SLIP_BACKWARD if d > 0 else SLIP_FORWARD  # repelling: leave the way sgn(0)=0 accelerates

    @staticmethod
    def _stick(model: BeltModel, t0: float, x0: float, t_limit: float):
        f, d0 = model.friction, float(model.stick_demand(t0, x0))
        return stick_segment(
            model.params, t0, x0, t_limit, d0, model.params.damping - f.b - f.kappa, abs(f.a)
        )

    def _slip(self, model: BeltModel, t0: float, x0: float, v0: float, s: int, t_limit: float):
        """One slip segment in direction s; returns (segment, hit) with hit = reached v_r = 0.

        With a friction plateau the slip is split at |v_r| = v_p: inside, the affine law (slip damping
        C - b); outside, a constant force (slip damping C). Crossing v_p ends the segment with hit = False
        and the next segment continues in the same direction from the same state (v is continuous there).
        """
        p = model.params
        f = model.friction
        m = model.mass
        vb0 = float(model.belt_velocity(t0))
        slope = float(p.belt_acceleration_at(t0))
        vp = f.plateau_speed
        outside = False
        if f.has_plateau:
            rel = s * (v0 - vb0)
            if rel > vp * (1 + PLATEAU_BAND):
                outside = True
            elif rel >= vp * (1 - PLATEAU_BAND):  # on it: go where the outer law accelerates
                _, force, kv = f.outer(s)
                acc = (force + kv * vb0 - p.damping * v0 - p.stiffness * x0) / m
                outside = s * (acc - slope) > 0
        if outside:
            b_eff, g0, kv = f.outer(s)
            seg = LinearSegment(
                m=m, c=p.damping - b_eff, k=p.stiffness, g0=g0 + kv * vb0, g1=kv * slope, x0=x0, v0=v0
            )

            def gap(tau):  # s v_r - v_p: positive while outside the plateau surface
                return s * (seg.state(tau)[1] - (vb0 + slope * tau)) - vp
        else:
            seg = LinearSegment(
                m=m,
                c=model.slip_damping(),
                k=p.stiffness,
                g0=f.a * s + f.kappa * vb0,
                g1=f.kappa * slope,
                x0=x0,
                v0=v0,
            )

            def gap(tau):  # s * v_r: positive while the slip lasts (and below v_p with a plateau)
                g = s * (seg.state(tau)[1] - (vb0 + slope * tau))
                return np.minimum(g, vp - g) if f.has_plateau else g

        def gap_rate(tau):
            rate = s * (seg.acceleration(tau) - slope)
            if not f.has_plateau or outside:
                return rate
            g = s * (seg.state(tau)[1] - (vb0 + slope * tau))
            return np.where(g <= vp - g, rate, -rate)

        tau_max = t_limit - t0
        vscale = max(abs(vb0), abs(f.a) / math.sqrt(p.stiffness * m), abs(v0), 1e-300)
        tol = self.graze_tolerance * vscale
        timescale = 2.0 * math.pi * math.sqrt(m / p.stiffness)
        if seg._alpha != 0.0:
            timescale = min(timescale, 2.0 * math.pi / abs(seg._alpha))
        h = timescale / self.samples_per_period

        def finish(tau_hit):
            if not f.has_plateau:
                return Segment(t0, t0 + tau_hit, s, seg), True
            rel = s * (float(seg.state(tau_hit)[1]) - (vb0 + slope * tau_hit))
            hit = (not outside) and rel < 0.5 * vp  # v_r = 0 (contact) rather than the plateau surface
            return Segment(t0, t0 + tau_hit, s, seg), hit

        # A slip that starts at v_r = 0 leaves it with zero gap: find a first positive sample.
        start = min(h, tau_max)
        while gap(start) <= 0.0 and start > 1e-13 * h:
            start *= 0.125
        if gap(start) <= 0.0:
            return finish(0.0)
        lo_tau, lo_gap = 0.0, 0.0
        tau_k = start
        window = WINDOW_SAMPLES[0]
        while True:
            grid = tau_k + h * np.arange(window)
            grid = grid[grid < tau_max]
            grid = np.append(grid, tau_max) if grid.size < window else grid
            values = gap(grid)
            taus = np.concatenate(([lo_tau], grid))
            gaps = np.concatenate(([lo_gap], values))
            event = self._first_event(taus, gaps, gap, gap_rate, tol, seg.velocity_curvature_bound)
            if event is not None:
                return finish(event)
            if grid[-1] >= tau_max or self._clear_to_the_end(seg, s, vb0, slope, vp, outside, grid[-1], tol):
                return Segment(t0, t_limit, s, seg), False
            # overlap the next window by one sample so a minimum of the gap that falls exactly on a
            # window boundary is still seen with both neighbours (a graze is never skipped)
            lo_tau, lo_gap = grid[-2], values[-2]
            tau_k = grid[-1]
            # a slip with no event yet is scanned in ever longer windows (same spacing h): a slip that lasts
            # thousands of oscillations costs a few array evaluations, not thousands of Python iterations
            window = min(2 * window, WINDOW_SAMPLES[1])

    @staticmethod
    def _clear_to_the_end(seg, s, vb0, slope, vp, outside, tau_from, tol) -> bool:
        """True when the slip provably lasts to the end of the run: at constant belt speed the gap is a
        constant plus s v_h, and the free velocity's envelope keeps it above ``tol`` for every tau >= tau_from
        (the window scan would find no event; this returns the same segment without scanning)."""
        if slope != 0.0:
            return False
        spread = seg.free_velocity_envelope(tau_from)
        if not math.isfinite(spread):
            return False
        centre = s * (seg.particular_velocity - vb0)  # s v_r without the free motion
        if outside:
            return centre - vp - spread > tol
        if not math.isfinite(vp):
            return centre - spread > tol
        return centre - spread > tol and vp - (centre + spread) > tol

    @staticmethod
    def _first_event(taus, gaps, gap, gap_rate, tol, curvature=None):
        """Earliest return to v_r = 0 within the sampled window: a crossing or a grazing touch.

        ``curvature(lo, hi)`` bounds |gap''| on [lo, hi]; a sampled minimum g_k with
        g_k - bound * (hi - lo)^2 / 2 > tol cannot hide a touch or a crossing (the true minimum is within
        (hi - lo) / 2 of a sample, so at most bound * (hi - lo)^2 / 8 below it) and needs no root search: the
        result is the same, found without evaluating the gap at every oscillation of a long slip."""
        # imported here: the config check at parse time builds every solver, and scipy.optimize is ~0.5 s
        from scipy.optimize import brentq

        nonpos = np.nonzero(gaps[1:] <= 0.0)[0]
        first_cross = nonpos[0] + 1 if nonpos.size else len(gaps)
        # interior local minima of the gap before the first crossing could hide a touch or a double root
        k = np.arange(1, min(first_cross, len(gaps) - 1))
        minima = k[(gaps[k] <= gaps[k - 1]) & (gaps[k] <= gaps[k + 1])]
        if curvature is not None and minima.size:
            lo, hi = taus[minima - 1], taus[minima + 1]
            clear = gaps[minima] - curvature(lo, hi) * (hi - lo) ** 2 / 2 > tol  # NaN: not clear
            minima = minima[~clear]
        for k in minima:
            lo, hi = taus[k - 1], taus[k + 1]
            r_lo, r_hi = gap_rate(lo), gap_rate(hi)
            if r_lo < 0.0 < r_hi:
                tau_min = brentq(gap_rate, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
            else:
                tau_min = taus[k]
            g_min = gap(tau_min)
            if g_min < -tol:  # a crossing the grid stepped over
                return brentq(gap, taus[k - 1], tau_min, xtol=1e-15, rtol=4 * np.finfo(float).eps)
            if g_min <= tol:
                return tau_min
        if first_cross < len(gaps):
            lo, hi = taus[first_cross - 1], taus[first_cross]
            if gaps[first_cross] == 0.0:
                return hi
            return brentq(gap, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
        return None
