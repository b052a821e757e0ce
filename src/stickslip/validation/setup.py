"""The ``validation`` config section (typed by ``stickslip.schema``) as objects: solvers, laws,
parameters and tolerances, each checking its physics at construction, the error naming its key."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..model.laws import FrictionLaw, LawModel, law_from_config
from ..model.params import BeltParams, ParameterError
from ..solvers.switch import SwitchSolver
from .compare import Tolerance
from .peer import PeerSettings


@dataclass(frozen=True)
class ValidationSetup:
    cfg: dict

    def _section(self, *keys):
        node = self.cfg
        for key in keys:
            node = node[key]
        return node

    @property
    def t_end(self) -> float:
        return float(self._section("t_end"))

    def solver(self) -> SwitchSolver:
        try:
            return SwitchSolver(**self._section("solver"))
        except (TypeError, ParameterError) as exc:
            raise ParameterError(f"validation.solver.{exc}") from None

    def peer(self) -> PeerSettings:
        entry = {k: v for k, v in self._section("peer").items() if k != "program"}
        try:
            return PeerSettings(**entry)
        except TypeError as exc:
            raise ParameterError(f"validation.peer: {exc}") from None

    def tolerances(self) -> dict[str, Tolerance]:
        tol = self._section("tolerances")
        return {
            k: Tolerance.from_config(f"validation.tolerances.{k}", tol.get(k))
            for k in ("time", "position", "closed_form")
        }

    def closed_form(self, name: str) -> bool:
        return bool(self._section("laws", name).get("closed_form", False))

    def law_names(self) -> list[str]:
        return list(self._section("laws"))

    def law(self, name: str) -> FrictionLaw:
        return law_from_config(self._section("laws", name, "law"), key=f"validation.laws.{name}.law")

    def params(self, name: str) -> BeltParams:
        overrides = self._section("laws", name).get("params", {})
        try:
            return BeltParams.from_mapping({**self._section("base_params"), **overrides})
        except ParameterError as exc:
            raise ParameterError(f"validation.laws.{name}.params.{exc}") from None

    def model(self, name: str) -> LawModel:
        return LawModel(self.params(name), self.law(name))

    def table_paths(self) -> list[str]:
        """Friction tables the laws read (DAG inputs of the peer rule)."""
        return [
            self._section("laws", n, "law")["path"]
            for n in self.law_names()
            if self._section("laws", n, "law").get("kind") == "tabulated"
        ]

    def check(self, producible: list[str]) -> None:
        """Build everything that can be built before any job runs; tables must exist or be rule outputs."""
        self.t_end, self.solver(), self.peer(), self.tolerances()
        for name in self.law_names():
            self.params(name)
            entry = self._section("laws", name, "law")
            if isinstance(entry, dict) and entry.get("kind") == "tabulated":
                path = entry.get("path")
                if path not in producible and not Path(str(path)).is_file():
                    raise ParameterError(
                        f"validation.laws.{name}.law.path: {path!r} neither exists nor is made by a rule"
                    )
            else:
                self.law(name)
        rt = self._section("round_trip")
        law_from_config(rt["curved_law"], key="validation.round_trip.curved_law")
        try:
            SwitchSolver(**(rt.get("curved_solver") or {}))
        except (TypeError, ParameterError) as exc:
            raise ParameterError(f"validation.round_trip.curved_solver: {exc}") from None
        from .methods import expand_methods

        expand_methods(self._section("methods_per_law")["methods"])
