"""The ``validation`` section (typed by ``stickslip.schema``) as the objects a job runs: solvers, laws,
parameters and the peer's settings, each checking its physics at construction, the error naming its key."""

from __future__ import annotations

from pathlib import Path

from ..model.laws import FrictionLaw, LawModel, law_from_config
from ..model.params import BeltParams, ParameterError
from ..schema import LawRuns, SwitchSettings, Validation, given
from ..solvers import make_solver
from ..solvers.switch import SwitchSolver


def switch_solver(settings: SwitchSettings | None, key: str) -> SwitchSolver:
    """The switch solver with these settings (None: its defaults); an unknown setting names ``key``."""
    try:
        return SwitchSolver(**given(settings))
    except (TypeError, ParameterError) as exc:
        raise ParameterError(f"{key}: {exc}") from None


def law(job: LawRuns, name: str) -> FrictionLaw:
    return law_from_config(given(job.laws[name].law), key=f"validation.laws.{name}.law")


def law_params(job: LawRuns, name: str) -> BeltParams:
    """The scene of one law: the section's base parameters, then the law entry's own."""
    try:
        return BeltParams(**{**given(job.base_params), **given(job.laws[name].params)})
    except ParameterError as exc:
        raise ParameterError(f"validation.laws.{name}.params.{exc}") from None


def law_model(job: LawRuns, name: str) -> LawModel:
    return LawModel(law_params(job, name), law(job, name))


def table_paths(job: LawRuns) -> list[str]:
    """Friction tables the laws read (DAG inputs of the peer rule)."""
    return [entry.law.path for entry in job.laws.values() if entry.law.kind == "tabulated"]


def check(validation: Validation, producible: list[str]) -> None:
    """Build everything that can be built before any job runs; tables must exist or be rule outputs."""
    from .methods import expand_methods

    switch_solver(validation.solver, "validation.solver")
    for name, entry in validation.laws.items():
        law_params(validation, name)
        path = getattr(entry.law, "path", None)
        if entry.law.kind != "tabulated" or path is None:
            law(validation, name)
        elif path not in producible and not Path(str(path)).is_file():  # a rule's table is read by the job
            raise ParameterError(
                f"validation.laws.{name}.law.path: {path!r} neither exists nor is made by a rule"
            )
    rt = validation.round_trip
    law_from_config(given(rt.curved_law), key="validation.round_trip.curved_law")
    switch_solver(rt.curved_solver, "validation.round_trip.curved_solver")
    for solver, settings, label in expand_methods(validation.methods_per_law.methods):
        try:
            make_solver(solver, **settings)
        except (ValueError, TypeError) as exc:
            raise ParameterError(f"validation.methods_per_law.methods: {label}: {exc}") from None
