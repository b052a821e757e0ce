"""The part every solve_ivp-based method shares: count, time, integrate, sample, record failures."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.integrate import solve_ivp

from ..model.equations import BeltModel
from .base import SolverStats, Timer, Trajectory, classify_phase, default_t_eval  # noqa: F401 (re-exported)


def integrate(
    model: BeltModel,
    rhs: Callable,
    t_end: float,
    t_eval: np.ndarray,
    *,
    method: str,
    rtol: float,
    atol: float,
    max_step: float,
    stick_tolerance: float,
    label: str,
    settings: dict,
    jac: Callable | None = None,
) -> Trajectory:
    """Integrate ``rhs`` from the model's initial state; a solver error or non-finite state is a failed run.

    ``rhs`` and ``jac`` are counted here, so the counters are the same for every method.
    """
    stats = SolverStats()
    counts = {"rhs": 0, "jac": 0}

    def counted_rhs(t, y):
        counts["rhs"] += 1
        return rhs(t, y)

    kwargs = {}
    if jac is not None:

        def counted_jac(t, y):
            counts["jac"] += 1
            return jac(t, y)

        kwargs["jac"] = counted_jac
    sol = None
    with Timer() as timer:
        try:
            sol = solve_ivp(
                counted_rhs,
                (0.0, t_end),
                [model.params.x0, model.params.v0],
                method=method,
                rtol=rtol,
                atol=atol,
                max_step=max_step,
                dense_output=True,
                **kwargs,
            )
        except (ValueError, ArithmeticError) as exc:  # e.g. a non-finite Jacobian
            stats.message = f"{type(exc).__name__}: {exc}"
    stats.cpu_time = timer.elapsed
    stats.rhs_evaluations = counts["rhs"]
    stats.jacobian_evaluations = counts["jac"]
    if sol is None or not sol.success:
        stats.status, stats.failures = "failed", 1
        stats.message = stats.message or str(sol.message)
        x = np.full(t_eval.shape, np.nan)
        v = np.full(t_eval.shape, np.nan)
    else:
        stats.steps = max(len(sol.t) - 1, 0)
        stats.min_step = float(np.min(np.diff(sol.t))) if len(sol.t) > 1 else float("nan")
        x, v = sol.sol(t_eval)
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
            stats.status, stats.message, stats.failures = "failed", "non-finite state", 1
    vb = model.belt_velocity(t_eval)
    return Trajectory(
        t=t_eval,
        x=x,
        v=v,
        phase=classify_phase(v, vb, stick_tolerance),
        belt_velocity=vb,
        stats=stats,
        method=label,
        settings=settings,
    )
