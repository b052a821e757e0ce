"""Methods study for a nonlinear law: the paper's single sign-function equation (and its smoothed version)
integrated by standard Runge-Kutta pairs, against the switch-model solver as the reference.

The existing methods study (``config/methods.yaml``) uses the affine law only; this checks that the ranking
of methods is not an artefact of it. Only the methods whose right-hand side is the single equation
M x'' + C x' + K x = -N mu(|v_r|) sgn(v_r) carry over to any law (``sign_rk``, ``smooth`` with an explicit
pair); Karnopp's band and Moreau-Jean are written for the affine law's coefficients and are not run here.
A law with a static/kinetic jump (mu(0+) < mu_static) cannot be written as one sign equation at all: the
sign form only knows mu(0+), so it is studied with continuous laws (Stribeck, 1/(1 + delta|v_r|)).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from ..model.laws import LawModel
from ..schema import LawMethod, MethodsPerLaw
from ..solvers import make_solver


@dataclass(frozen=True)
class SignLawModel(LawModel):
    """A law model as the paper's one equation with sgn(v_r) (what ode45 integrates)."""

    #: No affine coefficients: methods that need them (implicit Jacobians, Karnopp, Moreau) cannot run.
    friction = None

    def acceleration(self, t, x, v, sign=np.sign):
        p = self.params
        vr = v - self.belt_velocity(t)
        force = -p.normal_force * self.law.mu(vr) * sign(vr)
        return (force - p.damping * v - p.stiffness * x) / self.mass

    def rhs(self, t, y, sign=np.sign):
        return np.array([y[1], self.acceleration(t, y[0], y[1], sign=sign)])


def expand_methods(entries: Iterable[LawMethod]) -> list[tuple[str, dict, str]]:
    """Method entries -> (solver, settings, label), one per swept combination."""
    out = []
    for entry in entries:
        for settings in entry.combinations():
            shown = (f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}" for k, v in settings.items())
            out.append((entry.solver, settings, entry.solver + "[" + ",".join(shown) + "]"))
    return out


def model_for(solver: str, law_model: LawModel):
    """The model object a method takes: the law model (switch) or its single-equation form."""
    return law_model if solver == "switch" else SignLawModel(law_model.params, law_model.law)


def methods_study(law_model: LawModel, study: MethodsPerLaw, reference):
    """One record per method run: errors against the switch-solver reference, CPU time, work counters."""
    from ..analysis.errors import measure_run, segment_cycle_metrics

    t_end = study.t_end
    t_eval = np.linspace(0.0, t_end, int(round(t_end / study.output_dt)) + 1)
    ref = reference.solve(law_model, t_end, t_eval)
    ref_cycle = segment_cycle_metrics(reference.segments(law_model, t_end))  # to machine precision
    records = []
    for solver, settings, label in expand_methods(study.methods):
        _, record = measure_run(
            make_solver(solver, **settings),
            model_for(solver, law_model),
            t_end,
            t_eval,
            ref,
            ref_cycle,
            **study.timing.model_dump(),
        )
        records.append({"label": label, "solver": solver, **record})
    return records, ref_cycle
