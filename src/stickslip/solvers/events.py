"""The event-driven family (exact, switch) of the 1-DOF contract (``base.OneDofSolver``).

``solve()`` is the contract's; this family's ``_integrate`` is the phase loop (segment budget, the
zero-length guard, the set-valued decision at v_r = 0, the belt's stop as a scheduled event) and its
``_sample`` evaluates the segments on the output times. A subclass supplies only its phases: ``_phase`` (one
stick or slip phase and the mode after it), ``_mode_from_state`` and ``_contact_decision``, and, where it
integrates a model of its own kind, ``_integrated``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .base import (
    SLIP_BACKWARD,
    SLIP_FORWARD,
    STICK,
    OneDofSolver,
    Samples,
    SolverError,
    SolverStats,
    checked_t_end,
)


@dataclass(frozen=True)
class StickMotion:
    """The mass carried by the belt: x = x0 + vb0 tau + slope tau^2 / 2."""

    x0: float
    vb0: float
    slope: float

    def state(self, tau):
        if not isinstance(tau, float):  # one time stays a Python float: the same operations, no array
            tau = np.asarray(tau, dtype=float)
        return self.x0 + self.vb0 * tau + 0.5 * self.slope * tau * tau, self.vb0 + self.slope * tau + 0 * tau


@dataclass(frozen=True)
class Segment:
    t0: float
    t1: float
    phase: int
    motion: object  # LinearSegment | StickMotion

    def state(self, t):
        if isinstance(t, float):  # the phase loop's end states: the same subtraction without an array
            return self.motion.state(t - self.t0)
        return self.motion.state(np.asarray(t, dtype=float) - self.t0)


class EventDrivenSolver(OneDofSolver):
    """Base of the event-driven solvers: subclasses are dataclasses with ``name``, ``max_segments``,
    ``max_zero_length`` and ``settings``, and implement the phase hooks below."""

    max_segments: int
    max_zero_length: int
    records_segments = True

    # -- hooks ----------------------------------------------------------------------------------------
    def _mode_from_state(self, model, t: float, x: float, v: float):
        """Slip the way v_r points, or 'contact' (decided by ``_contact_decision``) where v_r = 0."""
        vr = v - float(model.belt_velocity(t))
        if vr > 0:
            return SLIP_FORWARD
        if vr < 0:
            return SLIP_BACKWARD
        return "contact"

    def _contact_decision(self, model, t: float, x: float):
        raise NotImplementedError

    def _phase(self, model, mode, t: float, x: float, v: float, t_limit: float, stats: SolverStats):
        """One phase from (t, x, v) in ``mode`` up to at most ``t_limit``: (Segment, mode after it, where
        'contact' means v_r = 0 and the next mode is decided there)."""
        raise NotImplementedError

    # -- the family's part of the contract -----------------------------------------------------------
    def _sample(self, segments: list[Segment], t_eval: np.ndarray, belt_velocity) -> Samples:
        x, v, phase = sample_segments(segments, t_eval)
        table = np.array([[s.t0, s.t1, s.phase] for s in segments]).reshape(-1, 3)
        return Samples(x, v, phase, segments=table)

    def segments(self, model, t_end: float, stats: SolverStats | None = None) -> list[Segment]:
        """The phases of the motion up to ``t_end`` (a ``SolverError`` when they cannot be built)."""
        stats = stats if stats is not None else SolverStats()
        return self._integrate(self._integrated(model), checked_t_end(t_end, self.name), stats)

    def _integrate(self, model, t_end: float, stats: SolverStats) -> list[Segment]:
        """The phase loop, on the integrated model up to a checked ``t_end``."""
        p = model.params
        stop = p.belt_stop_time
        t, x, v = 0.0, float(p.x0), float(p.v0)
        out: list[Segment] = []
        zero_run = 0
        mode = self._mode_from_state(model, t, x, v)
        while t < t_end:
            if len(out) >= self.max_segments:
                raise SolverError(
                    f"{self.name} solver: more than {self.max_segments} segments before t={t_end}"
                )
            if mode == "contact":
                mode = self._contact_decision(model, t, x)
                stats.events += 1
                continue
            t_limit = min(t_end, stop) if t < stop else t_end
            seg, next_mode = self._phase(model, mode, t, x, v, t_limit, stats)
            out.append(seg)
            zero_run = zero_run + 1 if seg.t1 - seg.t0 <= 1e-14 * max(1.0, abs(seg.t0)) else 0
            if zero_run > self.max_zero_length:
                raise SolverError(
                    f"{self.name} solver cannot proceed at t={t:.17g}, x={x:.17g}: "
                    f"{zero_run} zero-length segments in a row"
                )
            t = seg.t1
            x, v = (float(q) for q in seg.state(t))
            if next_mode == "contact" or mode == STICK:
                v = float(model.belt_velocity(t))  # snap to the belt: v_r is zero here by construction
            if next_mode != "contact" and t >= stop and seg.t0 < stop:
                next_mode = self._mode_from_state(model, t, x, v)  # the belt just stopped: decide again
            mode = next_mode
        return out


def sample_segments(segments: list[Segment], t_eval: np.ndarray):
    """Evaluate a piecewise solution at sorted ``t_eval``; samples past a failed solve are NaN.

    Each segment owns the samples in [t0, t1) (the last one also t1), found by binary search, so the cost is
    O(samples + segments log samples) even for runs with many thousands of segments.
    """
    x = np.full(t_eval.shape, np.nan)
    v = np.full(t_eval.shape, np.nan)
    phase = np.zeros(t_eval.shape, dtype=np.int8)
    if not segments:
        return x, v, phase
    starts = np.searchsorted(t_eval, [seg.t0 for seg in segments], side="left")
    ends = np.searchsorted(t_eval, [seg.t1 for seg in segments], side="left")
    ends[-1] = np.searchsorted(t_eval, segments[-1].t1, side="right")
    for seg, lo, hi in zip(segments, starts, ends):
        if hi <= lo:
            continue
        xs, vs = seg.state(t_eval[lo:hi])
        x[lo:hi], v[lo:hi] = xs, vs
        phase[lo:hi] = seg.phase
    return x, v, phase
