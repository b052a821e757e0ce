"""Turn the pipeline config into model objects: scene x reading x method -> (model, solver, run settings).

A *scene* holds the parameters a figure caption gives; a *reading* is one interpretation of the paper's
equations (friction variant, which sigma, which units) applied on top of it; a *method* names an
integration method and its settings. Every error names the config key at fault.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.equations import BeltModel
from ..model.friction import VARIANTS
from ..model.params import BeltParams, ParameterError
from ..solvers import make_solver


@dataclass(frozen=True)
class RunSpec:
    scene: str
    reading: str
    method: str
    params: BeltParams
    variant: str
    t_end: float
    output_dt: float
    transient: float
    count_window: float
    solver_settings: dict
    figure: str
    description: str

    @property
    def model(self) -> BeltModel:
        return BeltModel.build(self.params, self.variant)

    def solver(self):
        settings = dict(self.solver_settings)
        return make_solver(settings.pop("solver"), **settings)

    @property
    def t_eval(self) -> np.ndarray:
        n = int(round(self.t_end / self.output_dt))
        return np.linspace(0.0, n * self.output_dt, n + 1)

    def interpretation(self) -> dict:
        return {"reading": self.reading, "variant": self.variant, "sigma": self.params.sigma,
                "units": self.params.units}

    def scene_attrs(self) -> dict:
        return {"name": self.scene, "figure": self.figure, "description": self.description,
                "t_end": self.t_end, "output_dt": self.output_dt, "transient": self.transient,
                **self.params.as_dict()}


def _section(config: dict, *keys):
    node = config
    path = []
    for key in keys:
        path.append(key)
        if not isinstance(node, dict) or key not in node:
            raise ParameterError(f"{'.'.join(path)}: missing from the config")
        node = node[key]
    return node


def run_spec(config: dict, scene: str, reading: str, method: str) -> RunSpec:
    defaults = _section(config, "onedof", "defaults")
    scene_cfg = _section(config, "onedof", "scenes", scene)
    reading_cfg = _section(config, "onedof", "readings", reading)
    method_cfg = _section(config, "onedof", "methods", method)
    params = dict(defaults.get("params", {}))
    params.update(scene_cfg.get("params", {}))
    variant = reading_cfg.get("variant")
    if variant not in VARIANTS:
        raise ParameterError(f"onedof.readings.{reading}.variant: {variant!r} is not one of {VARIANTS}")
    for key in ("sigma", "units"):
        if key in reading_cfg:
            params[key] = reading_cfg[key]
    try:
        belt = BeltParams.from_mapping(params)
    except ParameterError as exc:
        raise ParameterError(f"onedof.scenes.{scene}.params.{exc}") from None
    run = {**{k: defaults[k] for k in ("t_end", "output_dt", "transient", "count_window") if k in defaults},
           **{k: scene_cfg[k] for k in ("t_end", "output_dt", "transient", "count_window") if k in scene_cfg}}
    for key in ("t_end", "output_dt"):
        if key not in run:
            raise ParameterError(f"onedof.scenes.{scene}.{key}: missing (and no default)")
        if not (isinstance(run[key], (int, float)) and np.isfinite(run[key]) and run[key] > 0):
            raise ParameterError(f"onedof.scenes.{scene}.{key}: must be a positive number, got {run[key]!r}")
    if "solver" not in method_cfg:
        raise ParameterError(f"onedof.methods.{method}.solver: missing")
    spec = RunSpec(
        scene=scene, reading=reading, method=method, params=belt, variant=variant,
        t_end=float(run["t_end"]), output_dt=float(run["output_dt"]),
        transient=float(run.get("transient", 0.0)), count_window=float(run.get("count_window", 18.0)),
        solver_settings=dict(method_cfg), figure=str(scene_cfg.get("figure", "")),
        description=str(scene_cfg.get("description", "")),
    )
    spec.solver()  # fail now, naming the key, if the method settings are wrong
    return spec


def figure_runs(config: dict, figure: str) -> list[tuple[str, str, str]]:
    """(scene, reading, method) triples a figure needs."""
    fig = _section(config, "onedof", "figures", figure)
    return [(fig["scene"], r, m) for r in fig["readings"] for m in fig["methods"]]
