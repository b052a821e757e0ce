"""The solve_ivp family (sign-RK, smoothed, Karnopp) of the 1-DOF contract (``base.OneDofSolver``).

``solve()`` is the contract's; this family's ``_integrate`` hands the method's right-hand side (and Jacobian,
where it has one) to scipy's ``solve_ivp`` with dense output, counting their evaluations so the counters mean
the same for every method, and its ``_sample`` evaluates the dense output on the output times and labels
stick by the method's band. A method supplies only ``_rhs`` (and ``_jac``, ``_stick_band``, ``label``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Literal

import numpy as np

from ..model.params import Positive, PositiveOrInf, parameter_set
from .base import OneDofSolver, Samples, SolverError, SolverStats, classify_phase

#: scipy.integrate.solve_ivp's method names.
IvpMethod = Literal["RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA"]


@parameter_set(frozen=False)
class IvpSolver(OneDofSolver):
    """Base of the solve_ivp methods: their common settings (a method redeclares a field to change its
    default); subclasses are dataclasses with a ``name`` and implement ``_rhs``."""

    method: IvpMethod = "RK45"
    rtol: Positive = 1e-6
    atol: Positive = 1e-9
    max_step: PositiveOrInf = np.inf

    # -- hooks ----------------------------------------------------------------------------------------
    def _rhs(self, model) -> Callable:
        """The right-hand side f(t, y), y = (x, v), this method integrates."""
        raise NotImplementedError

    def _jac(self, model) -> Callable | None:
        """Its Jacobian, for the implicit methods; None: solve_ivp estimates it where it needs one."""
        return None

    def _stick_band(self) -> float:
        """|v - V_b| [mm/s] below which a sample is labelled stick (these methods have no stick state)."""
        return self.stick_tolerance

    @property
    def label(self) -> str:
        return f"{self.name}_{self.method}"

    # -- the family's part of the contract -----------------------------------------------------------
    def _integrate(self, model, t_end: float, stats: SolverStats):
        # imported here: the config check at parse time builds every solver, and scipy.integrate is ~0.5 s
        from scipy.integrate import solve_ivp

        own_rhs, jac = self._rhs(model), self._jac(model)
        kwargs = {} if jac is None else {"jac": jac}

        def rhs(t, y):  # counted: the counters mean the same for every method
            stats.rhs_evaluations += 1
            return own_rhs(t, y)

        try:
            sol = solve_ivp(
                rhs,
                (0.0, t_end),
                [model.params.x0, model.params.v0],
                method=self.method,
                rtol=self.rtol,
                atol=self.atol,
                max_step=self.max_step,
                dense_output=True,
                **kwargs,
            )
        except (ValueError, ArithmeticError) as exc:  # e.g. a non-finite Jacobian
            raise SolverError(f"{type(exc).__name__}: {exc}") from None
        if not sol.success:
            raise SolverError(str(sol.message))
        stats.steps = max(len(sol.t) - 1, 0)
        return sol

    def _sample(self, sol, t_eval: np.ndarray, belt_velocity: np.ndarray) -> Samples:
        x, v = sol.sol(t_eval)
        finite = np.all(np.isfinite(x)) and np.all(np.isfinite(v))
        phase = classify_phase(v, belt_velocity, self._stick_band())
        return Samples(x, v, phase, failure="" if finite else "non-finite state")
