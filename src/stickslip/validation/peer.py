"""The mass on the belt written for an independent program: SUNDIALS CVODE (scikit-sundae).

Nothing here uses the switch or exact solvers. The model is written again from the equation of motion,
M x'' + C x' + K x = F, as a hybrid system for CVODE:

* slip in direction s: y = (x, v), y' = (v, (-N s mu(s v_r) - C v - K x) / M); CVODE's root finder stops at
  s v_r = 0 (falling) and records v = 0 (the displacement extrema) without stopping;
* stick: y' = (V_b, dV_b/dt), integrated by CVODE too, with root functions D -+ N mu_s, where
  D = M dV_b/dt + C V_b + K x is the force friction must supply to carry the mass; CVODE stops at release;
* at v_r = 0 the set-valued static friction decides: stick if |D| <= N mu_s, else slip the way D points.

CVODE (variable-order Adams, or BDF) with its own rootfinding (Illinois-type) is a different integrator, a
different event locator and a different stick computation (integrated, not the closed-form root), so
agreement checks the switch solver's phases, event location and dense output at once. Only the friction
law's formula (``law.mu_continued``, a one-line expression tested against its definition) is shared.
"""

from __future__ import annotations

import numpy as np

from ..model.laws import LawModel
from ..schema import Peer
from .cycle import EventRecord

#: CVODE steps of one phase at most (a phase of a 60 s run takes ~1e2).
MAX_NUM_STEPS = 200_000


def _cvode(rhs, events, n_events, terminal, direction, settings: Peer):
    import sksundae as sun

    events.terminal = terminal
    events.direction = direction
    return sun.cvode.CVODE(
        rhs,
        method=settings.method,
        rtol=settings.rtol,
        atol=settings.atol,
        eventsfn=events,
        num_events=n_events,
        max_num_steps=MAX_NUM_STEPS,
    )


def _slip_functions(s: int, law, m, c, k, n, vb):
    """CVODE's right-hand side and root functions for slip in direction s (3-argument signatures)."""

    def rhs(t_, y_, yp):
        yp[0] = y_[1]
        yp[1] = (-n * s * float(law.mu_continued(s * (y_[1] - vb))) - c * y_[1] - k * y_[0]) / m

    def events(t_, y_, ev):
        ev[0] = s * (y_[1] - vb)  # return to the belt velocity
        ev[1] = y_[1]  # displacement extremum

    return rhs, events


def peer_events(model: LawModel, t_end: float, settings: Peer):
    """Run the hybrid system to ``t_end`` with CVODE; (EventRecord, counters). Constant belt speed only."""
    p = model.params
    if p.belt_deceleration != 0.0:
        raise ValueError("peer model: written for a constant belt speed (belt_deceleration = 0)")
    m, c, k, n, vb = p.effective_mass, p.damping, p.stiffness, p.normal_force, p.belt_velocity
    law = model.law
    limit = n * law.static
    t, y = 0.0, np.array([p.x0, p.v0], dtype=float)
    onsets, releases, extrema = [], [], []
    counters = {"rhs_evaluations": 0, "phases": 0}

    def decide(x):
        demand = c * vb + k * x
        if demand > limit:
            return -1
        if demand < -limit:
            return 1
        return 0

    mode = 0 if y[1] == vb else int(np.sign(y[1] - vb))
    if mode == 0:
        mode = decide(y[0])
    previous = None
    while t < t_end:
        counters["phases"] += 1
        if mode == 0:

            def rhs(t_, y_, yp):
                yp[0] = vb
                yp[1] = 0.0

            def events(t_, y_, ev):
                demand = c * vb + k * y_[0]
                ev[0] = demand - limit
                ev[1] = -limit - demand

            solver = _cvode(rhs, events, 2, [True, True], [1, 1], settings)
        else:
            rhs, events = _slip_functions(mode, law, m, c, k, n, vb)
            solver = _cvode(rhs, events, 2, [True, False], [-1, 0], settings)
        result = solver.solve(np.array([t, t_end]), y)
        counters["rhs_evaluations"] += int(result.nfev)
        if not result.success:
            raise RuntimeError(f"CVODE failed at t={t}: {result.message}")
        fired = result.i_events if result.i_events is not None else np.zeros((0, 2))
        times = result.t_events if result.t_events is not None else np.zeros(0)
        states = result.y_events if result.y_events is not None else np.zeros((0, 2))
        stop = None
        for ti, yi, flags in zip(np.atleast_1d(times), np.atleast_2d(states), np.atleast_2d(fired)):
            if mode != 0 and flags[1] != 0 and flags[0] == 0:
                extrema.append((float(ti), float(yi[0])))
            elif flags[0] != 0 or (mode == 0 and flags[1] != 0):
                stop = (float(ti), np.array(yi, dtype=float), flags)
        if stop is None:
            break  # reached t_end
        t, y, flags = stop
        if mode == 0:
            releases.append((t, float(y[0])))
            y[1] = vb
            mode = -1 if flags[0] != 0 else 1
        else:
            y[1] = vb
            new = decide(y[0])
            if new == 0:
                onsets.append((t, float(y[0])))
            mode = new
        if previous is not None and t <= previous:
            raise RuntimeError(f"CVODE hybrid run makes no progress at t={t}")
        previous = t
    record = EventRecord(*(np.array(a, dtype=float).reshape(-1, 2) for a in (onsets, releases, extrema)))
    return record, counters
