"""The exact event-driven solver, compiled: the pipeline's method ``exact``.

:class:`CompiledExactSolver` runs the reference :class:`stickslip.solvers.exact.ExactSwitchSolver`'s
algorithm (same settings, events, counters, failures and exceptions) as one numba function over the model's
numbers, and samples its segments there too (:mod:`stickslip.solvers.exact_kernel`: how, and how closely the
two agree). It accepts exactly the models the reference accepts and refuses the others with its error.

numba is imported on the first solve, not when the solver is built: the config check at parse time builds
every solver, and a job that only reads trajectories never compiles anything. The compiled functions are
cached on disk (``__pycache__``), so a process after the first pays only the cache load.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..model.equations import BeltModel
from ..model.params import parameter_set
from . import exact
from .base import Samples, SolverError, SolverStats
from .events import Segment, StickMotion
from .exact import ExactSwitchSolver
from .linear import LinearSegment

__all__ = ["CompiledExactSolver", "model_vector", "python_reference", "table_segments"]


def model_vector(model: BeltModel, stick_a: float | None = None) -> np.ndarray:
    """The numbers the kernel reads (``exact_kernel.P_*``): M, C, K, a, b, kappa, v_p, the stick limit's a
    (``stick_a``, default the friction's own a), x0, v0, V_b, deceleration, belt stop time."""
    p, f = model.params, model.friction
    return np.array(
        [
            model.mass,
            p.damping,
            p.stiffness,
            f.a,
            f.b,
            f.kappa,
            f.plateau_speed,
            f.a if stick_a is None else stick_a,
            p.x0,
            p.v0,
            p.belt_velocity,
            p.belt_deceleration,
            p.belt_stop_time,
        ],
        dtype=float,
    )


@dataclass
class _Table:
    """The kernel's result: segment rows (``exact_kernel.SEG_COLUMNS``) and the model's M, K to sample."""

    rows: np.ndarray
    m: float
    k: float


@parameter_set(frozen=False)
class CompiledExactSolver(ExactSwitchSolver):
    """The exact solver compiled with numba; settings, name and results as ``ExactSwitchSolver``'s."""

    name: str = "exact"
    #: ``"python"``: run the reference's phase loop and sampling instead (``python_reference``), with this
    #: object's settings and hooks. Not a setting: results agree either way.
    backend: ClassVar[str] = "compiled"

    def _stick_a(self, model: BeltModel) -> float:
        """The a of the stick limit |D| <= |a| and of the decision at v_r = 0 (a subclass may raise it)."""
        return model.friction.a

    def _integrate(self, model, t_end: float, stats: SolverStats):
        if self.backend == "python" or not isinstance(model, BeltModel):  # (no other model arrives here)
            return super()._integrate(model, t_end, stats)
        from . import exact_kernel as kernel  # lazy: numba's import and cache load only when solving

        window0, window1 = exact.WINDOW_SAMPLES
        rows, n, steps, events, status, t, x, zero_run, nan_x = kernel.run(
            model_vector(model, self._stick_a(model)),
            float(t_end),
            int(self.samples_per_period),
            float(self.graze_tolerance),
            int(self.max_segments),
            int(self.max_zero_length),
            int(window0),
            int(window1),
        )
        stats.steps += int(steps)
        stats.events += int(events)
        if status == kernel.TOO_MANY_SEGMENTS:
            raise SolverError(f"{self.name} solver: more than {self.max_segments} segments before t={t_end}")
        if status == kernel.ZERO_LENGTH:
            raise SolverError(
                f"{self.name} solver cannot proceed at t={t:.17g}, x={x:.17g}: "
                f"{zero_run} zero-length segments in a row"
            )
        if status == kernel.ROOT_NAN:  # scipy's brentq raises these; the callers tell them apart by text
            raise ValueError(f"The function value at x={nan_x} is NaN; solver cannot continue.")
        if status == kernel.ROOT_SIGN:
            raise ValueError("f(a) and f(b) must have different signs")
        if status == kernel.ROOT_CONVERGENCE:
            raise RuntimeError(
                f"Failed to converge after {kernel.BRENT_MAXITER} iterations, value is {nan_x}"
            )
        return _Table(rows[:n], model.mass, model.params.stiffness)

    def _sample(self, raw, t_eval: np.ndarray, belt_velocity) -> Samples:
        if not isinstance(raw, _Table):
            return super()._sample(raw, t_eval, belt_velocity)
        from . import exact_kernel as kernel

        t_eval = np.ascontiguousarray(t_eval, dtype=float)
        x, v, phase = kernel.sample(raw.rows, len(raw.rows), raw.m, raw.k, t_eval)
        return Samples(x, v, phase, segments=raw.rows[:, :3].copy())

    def segments(self, model, t_end: float, stats: SolverStats | None = None) -> list[Segment]:
        """The phases up to ``t_end`` as the reference's ``Segment`` objects (closed forms included)."""
        raw = super().segments(model, t_end, stats)  # the kernel's table, or the reference's segments
        return raw if isinstance(raw, list) else table_segments(raw)


def python_reference(solver: CompiledExactSolver) -> CompiledExactSolver:
    """A copy of ``solver`` (same settings, same subclass hooks) that solves with the pure-Python reference
    (``ExactSwitchSolver``'s phase loop and ``events.sample_segments``): the tests' oracle."""
    twin = copy.copy(solver)
    twin.backend = "python"
    return twin


def table_segments(table: _Table) -> list[Segment]:
    """The kernel's rows as ``Segment`` objects with their closed-form motions."""
    out = []
    for t0, t1, phase, x0, v0, c, g0, g1 in table.rows.tolist():
        phase = int(phase)
        if phase == 0:
            motion = StickMotion(x0, v0, g1)
        else:
            motion = LinearSegment(m=table.m, c=c, k=table.k, g0=g0, g1=g1, x0=x0, v0=v0)
        out.append(Segment(t0, t1, phase, motion))
    return out
