"""Layer 2: integration methods behind one interface, ``solve(model, t_end, t_eval) -> Trajectory``."""

from importlib import import_module

from .base import (
    SLIP_BACKWARD,
    SLIP_FORWARD,
    STICK,
    OneDofSolver,
    SolverError,
    SolverStats,
    Trajectory,
)

#: Method registry: config ``solver`` name -> (module, class). Later methods register here. The modules are
#: imported on first use (module ``__getattr__``): a job that only reads trajectories and draws them need not
#: import scipy's optimisers and integrators (~0.3 s of every such job's start).
REGISTRY = {
    "exact": ("exact_compiled", "CompiledExactSolver"),  # numba; the pure-Python reference: ExactSwitchSolver
    "sign_rk": ("sign_rk", "SignRungeKutta"),
    "smooth": ("smooth", "SmoothedSign"),
    "karnopp": ("karnopp", "Karnopp"),
    "moreau": ("moreau", "MoreauJean"),
    "switch": ("switch", "SwitchSolver"),  # any friction law (model/laws.py); affine laws: agrees with exact
}
_MODULE_OF = {cls: module for module, cls in REGISTRY.values()}
_MODULE_OF["ExactSwitchSolver"] = "exact"  # the exact method's pure-Python reference (tests, benchmarks)


def __getattr__(name: str):
    if name in _MODULE_OF:
        return getattr(import_module(f".{_MODULE_OF[name]}", __name__), name)
    if name == "METHODS":  # config ``solver`` name -> class
        return {key: __getattr__(cls) for key, (_, cls) in REGISTRY.items()}
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def make_solver(name: str, **settings):
    """Instantiate a method by its config name; unknown names/settings name the key in the error."""
    from ..model.params import ParameterError

    if name not in REGISTRY:
        raise ParameterError(f"solver: {name!r} is not one of {sorted(REGISTRY)}")
    try:
        solver = __getattr__(REGISTRY[name][1])(**settings)  # settings are checked at construction
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"solver settings for {name!r}: {exc}") from None
    return solver


__all__ = [
    "SLIP_BACKWARD",
    "SLIP_FORWARD",
    "STICK",
    "OneDofSolver",
    "SolverError",
    "SolverStats",
    "Trajectory",
    "ExactSwitchSolver",
    "CompiledExactSolver",
    "SignRungeKutta",
    "SwitchSolver",
    "METHODS",
    "REGISTRY",
    "make_solver",
]
