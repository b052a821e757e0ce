"""Layer 2: integration methods behind one interface, ``solve(model, t_end, t_eval) -> Trajectory``."""

from .base import SLIP_BACKWARD, SLIP_FORWARD, STICK, SolverError, SolverStats, Trajectory, check_settings
from .exact import ExactSwitchSolver
from .karnopp import Karnopp  # noqa: E402
from .moreau import MoreauJean  # noqa: E402
from .sign_rk import SignRungeKutta
from .smooth import SmoothedSign  # noqa: E402
from .switch import SwitchSolver  # noqa: E402

#: Method registry: config ``solver`` name -> class. Later methods register here.
METHODS = {"exact": ExactSwitchSolver, "sign_rk": SignRungeKutta}
METHODS["smooth"] = SmoothedSign
METHODS["karnopp"] = Karnopp
METHODS["moreau"] = MoreauJean
METHODS["switch"] = SwitchSolver  # any friction law (model/laws.py); affine laws: agrees with exact


def make_solver(name: str, **settings):
    """Instantiate a method by its config name; unknown names/settings name the key in the error."""
    from ..model.params import ParameterError

    if name not in METHODS:
        raise ParameterError(f"solver: {name!r} is not one of {sorted(METHODS)}")
    try:
        solver = METHODS[name](**settings)
        check_settings(solver)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"solver settings for {name!r}: {exc}") from None
    return solver


__all__ = [
    "SLIP_BACKWARD",
    "SLIP_FORWARD",
    "STICK",
    "SolverError",
    "SolverStats",
    "Trajectory",
    "ExactSwitchSolver",
    "SignRungeKutta",
    "SwitchSolver",
    "METHODS",
    "make_solver",
]
