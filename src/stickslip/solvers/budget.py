"""Work budget for methods that can stall (step-size collapse at the sign discontinuity): the model's
``rhs`` and ``acceleration`` raise :class:`BudgetExceeded` past a count of evaluations or of CPU time, and
``run_with_budget`` records that as a failed ``Trajectory`` (message 'budget: ...'), data instead of a hang.
"""

from __future__ import annotations

import time

import numpy as np

from ..model.params import Count, PositiveOrInf, checked_arguments
from .base import SolverStats, Trajectory, default_t_eval


class BudgetExceeded(RuntimeError):
    pass


class _BudgetedModel:
    def __init__(self, model, max_rhs: int, max_cpu: float):
        self._model = model
        self._max_rhs = max_rhs
        self._deadline = time.process_time() + max_cpu
        self.calls = 0

    def __getattr__(self, name):
        return getattr(self._model, name)

    def _tick(self):
        self.calls += 1
        if self.calls > self._max_rhs:
            raise BudgetExceeded(f"budget: more than {self._max_rhs} RHS evaluations")
        if self.calls % 1000 == 0 and time.process_time() > self._deadline:
            raise BudgetExceeded(f"budget: CPU time limit exceeded after {self.calls} RHS evaluations")

    def rhs(self, t, y, **kw):
        self._tick()
        return self._model.rhs(t, y, **kw)

    def acceleration(self, t, x, v, **kw):
        self._tick()
        return self._model.acceleration(t, x, v, **kw)


def run_with_budget(solver, model, t_end, t_eval, max_rhs: int = 2_000_000, max_cpu: float = 20.0):
    """solver.solve under a work budget; a stall becomes a failed trajectory with its counters.

    A fixed-step solver (``fixed_step = True``, e.g. Moreau-Jean) does t_end / h steps, known before it runs,
    and cannot stall: the RHS count does not apply to it, only the CPU limit (a safety net)."""
    if getattr(solver, "fixed_step", False):
        max_rhs = float("inf")
    proxy = _BudgetedModel(model, max_rhs, max_cpu)
    start = time.process_time()
    try:
        return solver.solve(proxy, t_end, t_eval)
    except BudgetExceeded as exc:
        t_eval = np.asarray(t_eval, dtype=float)
        stats = SolverStats(
            rhs_evaluations=proxy.calls,
            status="failed",
            message=str(exc),
            failures=1,
            cpu_time=time.process_time() - start,
        )
        return Trajectory.failed(
            t_eval,
            model.belt_velocity(t_eval),
            stats,
            getattr(solver, "name", type(solver).__name__),
            getattr(solver, "settings", {}),
        )


class BudgetedSolver:
    """A solver under a work budget: ``solve`` returns a failed trajectory instead of stalling.

    Use a count of right-hand-side evaluations (deterministic) rather than CPU time where results must be
    reproducible from machine to machine.
    """

    @checked_arguments(max_rhs=Count, max_cpu=PositiveOrInf)
    def __init__(self, inner, max_rhs: int, max_cpu: float = float("inf")):
        self.inner, self.max_rhs, self.max_cpu = inner, int(max_rhs), float(max_cpu)

    @property
    def name(self):
        return self.inner.name

    @property
    def settings(self):
        return {**self.inner.settings, "budget_max_rhs": self.max_rhs, "budget_max_cpu": self.max_cpu}

    def solve(self, model, t_end, t_eval=None):
        t_eval = default_t_eval(t_end, t_eval)
        return run_with_budget(self.inner, model, t_end, t_eval, max_rhs=self.max_rhs, max_cpu=self.max_cpu)
