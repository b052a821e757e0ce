"""Turn the pipeline config into model objects: scene x reading x method -> (model, solver, run settings).

A *scene* holds the parameters a figure caption gives; a *reading* is one interpretation of the paper's
equations (friction variant, which sigma, which units) applied on top of it; a *method* names an
integration method and its settings. Every error names the config key at fault.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.metrics import PAPER_COUNT_WINDOW
from ..model.equations import BeltModel
from ..model.friction import VARIANTS
from ..model.params import BeltParams, ParameterError
from ..solvers import make_solver
from ..solvers.base import sample_times
from ..solvers.budget import BudgetedSolver


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
        """The configured method; with ``budget: {max_rhs: N}`` a stall becomes a failed run."""
        settings = dict(self.solver_settings)
        budget = settings.pop("budget", None)
        solver = make_solver(settings.pop("solver"), **settings)
        if budget is not None:
            try:
                solver = BudgetedSolver(solver, **budget)
            except (TypeError, ValueError) as exc:
                raise ParameterError(f"onedof.methods.{self.method}.budget: {exc}") from None
        return solver

    @property
    def t_eval(self) -> np.ndarray:
        return sample_times(self.t_end, self.output_dt)

    def interpretation(self) -> dict:
        return {
            "reading": self.reading,
            "variant": self.variant,
            "sigma": self.params.sigma,
            "units": self.params.units,
            "plateau_speed": self.params.plateau_speed,
            "equation": EQUATIONS[self.variant],
        }

    def scene_attrs(self) -> dict:
        return {
            "name": self.scene,
            "figure": self.figure,
            "description": self.description,
            "t_end": self.t_end,
            "output_dt": self.output_dt,
            "transient": self.transient,
            **self.params.as_dict(),
        }


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
    for key in READING_PARAMS:
        if key in reading_cfg:
            params[key] = reading_cfg[key]
    try:
        belt = BeltParams.from_mapping(params)
    except ParameterError as exc:
        raise ParameterError(f"onedof.scenes.{scene}.params.{exc}") from None
    run = {
        **{k: defaults[k] for k in ("t_end", "output_dt", "transient", "count_window") if k in defaults},
        **{k: scene_cfg[k] for k in ("t_end", "output_dt", "transient", "count_window") if k in scene_cfg},
        **{k: reading_cfg[k] for k in ("output_dt",) if k in reading_cfg},
    }
    for key in ("t_end", "output_dt"):
        if key not in run:
            raise ParameterError(f"onedof.scenes.{scene}.{key}: missing (and no default)")
        if not (isinstance(run[key], (int, float)) and np.isfinite(run[key]) and run[key] > 0):
            raise ParameterError(f"onedof.scenes.{scene}.{key}: must be a positive number, got {run[key]!r}")
    if "solver" not in method_cfg:
        raise ParameterError(f"onedof.methods.{method}.solver: missing")
    spec = RunSpec(
        scene=scene,
        reading=reading,
        method=method,
        params=belt,
        variant=variant,
        t_end=float(run["t_end"]),
        output_dt=float(run["output_dt"]),
        transient=float(run.get("transient", 0.0)),
        count_window=float(run.get("count_window", PAPER_COUNT_WINDOW)),
        solver_settings=dict(method_cfg),
        figure=str(scene_cfg.get("figure", "")),
        description=str(scene_cfg.get("description", "")),
    )
    spec.solver()  # fail now, naming the key, if the method settings are wrong
    return spec


EQUATIONS = {
    "eq3_printed": "Eq. 3 as printed: F = mu_s N (sgn(v_r) - sigma v_r)",
    "eq4_printed": "Eq. 4 as printed: (C + mu_s N sigma) x' ... = mu_s N sgn(v_r) + sigma V_b",
    "consistent": (
        "F = -mu_s N (sgn(v_r) - sigma v_r'), v_r' = v_r clipped at +-plateau_speed (inf: no plateau)"
    ),
}

#: Keys a reading may set on top of a scene's parameters (which sigma, which units, a friction plateau).
READING_PARAMS = ("sigma", "units", "plateau_speed")


@dataclass(frozen=True)
class SweepSpec:
    """One parameter sweep (Figs. 10-14 and the belt-speed sweep) for one reading.

    ``values`` are the paper's values (time series are stored for each); ``dense`` is >= 50 points over the
    same range (metrics only). ``linked`` parameters follow the swept one proportionally (N = 10 M)."""

    name: str
    figure: str
    parameter: str
    values: tuple
    dense: tuple
    linked: dict
    units: str
    long_name: str
    base: RunSpec
    coord_scale: str = "linear"
    law: object = None
    """Any friction law (model/laws.py) replacing the reading's (switch solver); None: the reading's."""

    def axis(self, dense: bool):
        from ..analysis.sweep import SweepAxis

        return SweepAxis(
            self.parameter,
            self.dense if dense else self.values,
            units=self.units,
            long_name=self.long_name,
            linked=dict(self.linked),
        )


def sweep_spec(config: dict, sweep: str, reading: str) -> SweepSpec:
    """Resolve ``onedof.sweeps.<sweep>`` for a reading; every error names the key."""
    cfg = _section(config, "onedof", "sweeps", sweep)
    where = f"onedof.sweeps.{sweep}"
    base = run_spec(config, cfg.get("scene", "fig02"), reading, cfg.get("method", "exact"))
    param = cfg.get("parameter")
    from dataclasses import fields as _fields

    known = {f.name for f in _fields(BeltParams)}
    if param not in known:
        raise ParameterError(f"{where}.parameter: {param!r} is not a parameter ({sorted(known)})")
    values = cfg.get("values")
    if (
        not isinstance(values, list)
        or not values
        or not all(isinstance(v, (int, float)) and np.isfinite(v) for v in values)
    ):
        raise ParameterError(f"{where}.values: must be a non-empty list of finite numbers")
    dense_cfg = cfg.get("dense", {})
    try:
        start, stop, num = float(dense_cfg["start"]), float(dense_cfg["stop"]), int(dense_cfg["num"])
    except (KeyError, TypeError, ValueError):
        raise ParameterError(f"{where}.dense: needs start, stop, num") from None
    if num < 2 or not (np.isfinite(start) and np.isfinite(stop)) or start >= stop:
        raise ParameterError(f"{where}.dense: need start < stop and num >= 2")
    scale = dense_cfg.get("scale", "linear")
    if scale not in ("linear", "log"):
        raise ParameterError(f"{where}.dense.scale: {scale!r} is not linear or log")
    dense = np.geomspace(start, stop, num) if scale == "log" else np.linspace(start, stop, num)
    linked = cfg.get("linked", {}) or {}
    for k, factor in linked.items():
        if k not in known or not isinstance(factor, (int, float)):
            raise ParameterError(f"{where}.linked.{k}: must name a parameter with a numeric factor")
    for v in list(values) + [start, stop]:  # every point must be a valid parameter set
        try:
            base.params.with_(**{param: float(v)}, **{k: f * float(v) for k, f in linked.items()})
        except ParameterError as exc:
            raise ParameterError(f"{where}.values: {exc}") from None
    law = None
    if "law" in cfg:
        from ..model.laws import law_from_config

        law = law_from_config(cfg["law"], key=f"{where}.law")
        if base.solver_settings.get("solver") != "switch":
            raise ParameterError(
                f"{where}.method: a sweep with a friction law needs a method whose solver is 'switch' (the "
                f"exact solver handles the readings' affine laws only), got {cfg.get('method', 'exact')!r}"
            )
    return SweepSpec(
        name=sweep,
        figure=str(cfg.get("figure", "")),
        parameter=param,
        values=tuple(float(v) for v in values),
        dense=tuple(float(v) for v in dense),
        linked=dict(linked),
        units=str(cfg.get("units", "1")),
        long_name=str(cfg.get("long_name", param)),
        base=base,
        coord_scale=scale,
        law=law,
    )


def figure_runs(config: dict, figure: str) -> list[tuple[str, str, str]]:
    """(scene, reading, method) triples a figure needs."""
    fig = _section(config, "onedof", "figures", figure)
    return [(fig["scene"], r, m) for r in fig["readings"] for m in fig["methods"]]
