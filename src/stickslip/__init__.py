"""Reference replication of a stick-slip friction vibration study.

Your own scenario (``stickslip.api``; the ``stickslip`` console command does the same from a shell):

* ``stickslip.simulate(mu_s=0.6, damping=1.0)``: one 1-DOF run (any parameters, reading, friction law,
  method) as an ``xarray.Dataset`` with the paper's metrics (amplitude, frequency, stick and slip time);
* ``stickslip.simulate_fe("section9_kinematic", speed=0.5, t_end=0.1)``: one beam-on-disc scene.

``output="run.nc"`` writes the dataset the pipeline would write. Command line: ``stickslip --help``
(``run``, ``fe``, ``laws``, ``claims``, ``show``); the API's manual: ``help(stickslip.api)``.

Layers, each importing only from the ones listed before it:
``model``, ``solvers``, ``analysis``, ``fe``, ``io``; then ``studies`` (config in, dataset out), ``pipeline``
(the typed config), ``presentation`` (figures, the page) and ``api``/``cli`` on top.
"""

from ._version import __version__

#: The public functions, loaded on first use: ``import stickslip`` stays cheap (no numpy, xarray, scipy).
_API = {"simulate": "api", "simulate_fe": "api"}

__all__ = ["simulate", "simulate_fe", "__version__"]


#: Submodules reachable as attributes without an import of their own (``help(stickslip.api)``).
_SUBMODULES = ("api", "cli", "catalogue")


def __getattr__(name: str):
    from importlib import import_module

    if name in _API:
        return getattr(import_module(f".{_API[name]}", __name__), name)
    if name in _SUBMODULES:
        return import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted([*globals(), *_API, *_SUBMODULES])
