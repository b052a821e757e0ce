"""From the validated config to run specifications: scene x reading x method, a sweep, a dense map.

The config has been checked by the typed layer (``stickslip.pipeline.config.validate_config``: types, bounds,
references between sections, which solver a friction law needs) before anything here runs. What is left is
resolution: merge defaults, scene, reading and method into a ``RunSpec`` and build the science objects
(``BeltParams``, the solver, a friction law), whose constructors check physics; their errors are re-keyed
to the config path they came from, so ``validate_config`` (which resolves every run at parse time) names it.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ..analysis.metrics import PAPER_COUNT_WINDOW
from ..analysis.sweep import SweepAxis, chunk_count, grid_size, run_points
from ..model.equations import BeltModel
from ..model.laws import FrictionLaw, LawModel, law_from_config
from ..model.params import BeltParams, ParameterError
from ..solvers import make_solver
from ..solvers.base import sample_times
from ..solvers.budget import BudgetedSolver

#: The fields of a 1-DOF job's config that the perturbation ensemble perturbs (stickslip.ensemble.declared):
#: the model's parameters wherever they are set, the readings' friction parameters, the solvers' step and
#: tolerance settings, and the parameter values a sweep or the critical-speed continuation runs at. Never
#: the windows and samplings of the output (t_end, output_dt, transient, count_window, eq6.f_max, the stick
#: label's tolerance) nor counts (num, points, bins, budgets).
PERTURBED_FIELDS = (
    "params.*",
    "readings.*.sigma",
    "readings.*.plateau_speed",
    "methods.*.rtol",
    "methods.*.atol",
    "methods.*.h",
    "methods.*.max_step",
    "methods.*.first_step",
    "methods.*.eta",
    "sweeps.*.values",
    "sweeps.*.linked.*",
    "sweeps.*.dense.start",
    "sweeps.*.dense.stop",
    "critical_speed.start",
    "critical_speed.stop",
)

#: Run-length keys a scene (or a dense map) sets over ``onedof.defaults``.
RUN_LENGTHS = ("t_end", "output_dt", "transient", "count_window")
#: Keys a reading may set on top of a scene's parameters (which sigma, which units, a friction plateau).
READING_PARAMS = ("sigma", "units", "plateau_speed")

EQUATIONS = {
    "eq3_printed": "Eq. 3 as printed: F = mu_s N (sgn(v_r) - sigma v_r)",
    "eq4_printed": "Eq. 4 as printed: (C + mu_s N sigma) x' ... = mu_s N sgn(v_r) + sigma V_b",
    "consistent": (
        "F = -mu_s N (sgn(v_r) - sigma v_r'), v_r' = v_r clipped at +-plateau_speed (inf: no plateau)"
    ),
}


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
    law: FrictionLaw | None = None
    """The scene's own friction law (``onedof.scenes.<scene>.law``, switch solver); None: the reading's."""

    @property
    def model(self) -> BeltModel | LawModel:
        if self.law is not None:
            return LawModel(self.params, self.law)
        return BeltModel.build(self.params, self.variant)

    @property
    def friction(self):
        """The friction the metrics read (``force(v, v_b)``): the reading's, or the scene's law at N."""
        if self.law is not None:
            return self.model.slip_friction
        return self.model.friction

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
        out = {
            "reading": self.reading,
            "variant": self.variant,
            "sigma": self.params.sigma,
            "units": self.params.units,
            "plateau_speed": self.params.plateau_speed,
            "equation": EQUATIONS[self.variant],
        }
        if self.law is not None:  # the scene's law replaces the reading's friction (mu_s, sigma unused)
            out["friction_law"] = repr(self.law)
            out["equation"] = "M x'' + C x' + K x = F, F from friction_law (the reading's friction unused)"
        return out

    def scene_attrs(self) -> dict:
        out = {
            "name": self.scene,
            "figure": self.figure,
            "description": self.description,
            "t_end": self.t_end,
            "output_dt": self.output_dt,
            "transient": self.transient,
            **self.params.as_dict(),
        }
        if self.law is not None:
            out["friction_law"] = repr(self.law)
        return out


def run_config(config: dict, reading: str, method: str) -> dict:
    """The config with only ``reading`` and ``method`` of the 1-DOF readings and methods: what one run reads.
    An ensemble of the run perturbs this, so another method's step settings (an ode45 rtol beside an exact
    run) never make a ``step`` member that repeats the run unchanged."""
    onedof = dict(config["onedof"])
    onedof["readings"] = {reading: onedof["readings"][reading]}
    onedof["methods"] = {method: onedof["methods"][method]}
    return {**config, "onedof": onedof}


def run_spec(config: dict, scene: str, reading: str, method: str) -> RunSpec:
    """Scene parameters over the defaults, the reading's interpretation over them, and the method."""
    onedof = config["onedof"]
    defaults, scene_cfg = onedof["defaults"], onedof["scenes"][scene]
    reading_cfg, method_cfg = onedof["readings"][reading], onedof["methods"][method]
    params = {**defaults.get("params", {}), **(scene_cfg.get("params") or {})}
    params.update({k: reading_cfg[k] for k in READING_PARAMS if k in reading_cfg})
    try:
        belt = BeltParams.from_mapping(params)
    except ParameterError as exc:
        raise ParameterError(f"onedof.scenes.{scene}.params.{exc}") from None
    run = {k: defaults[k] for k in RUN_LENGTHS if k in defaults}
    run |= {k: scene_cfg[k] for k in RUN_LENGTHS if k in scene_cfg}
    run |= {k: reading_cfg[k] for k in ("output_dt",) if k in reading_cfg}
    spec = RunSpec(
        scene=scene,
        reading=reading,
        method=method,
        params=belt,
        variant=reading_cfg["variant"],
        t_end=float(run["t_end"]),
        output_dt=float(run["output_dt"]),
        transient=float(run.get("transient", 0.0)),
        count_window=float(run.get("count_window", PAPER_COUNT_WINDOW)),
        solver_settings=dict(method_cfg),
        figure=str(scene_cfg.get("figure") or ""),
        description=str(scene_cfg.get("description") or ""),
        law=_law(scene_cfg, f"onedof.scenes.{scene}"),
    )
    spec.solver()  # the solver checks its settings at construction: fail now, naming the method
    if spec.law is not None and spec.solver_settings.get("solver") != "switch":
        raise ParameterError(
            f"onedof.scenes.{scene}.law: a {spec.law.kind!r} friction law is solved by the 'switch' solver "
            f"only; method {method!r} uses {spec.solver_settings.get('solver')!r}"
        )
    return spec


def baseline_spec(config: dict, reading: str | None = None) -> RunSpec:
    """The paper's baseline run (``onedof.baseline``), under its own reading or ``reading``."""
    base = config["onedof"]["baseline"]
    return run_spec(config, base["scene"], reading or base["reading"], base["method"])


def figure_runs(config: dict, figure: str) -> list[tuple[str, str, str]]:
    """(scene, reading, method) triples a figure needs."""
    fig = config["onedof"]["figures"][figure]
    return [(fig["scene"], r, m) for r in fig["readings"] for m in fig["methods"]]


def _law(cfg: dict, key: str) -> FrictionLaw | None:
    return law_from_config(cfg["law"], key=f"{key}.law") if cfg.get("law") else None


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

    def axis(self, dense: bool) -> SweepAxis:
        return SweepAxis(
            self.parameter,
            self.dense if dense else self.values,
            units=self.units,
            long_name=self.long_name,
            linked=dict(self.linked),
        )


def sweep_spec(config: dict, sweep: str, reading: str) -> SweepSpec:
    """``onedof.sweeps.<sweep>`` for one reading; every point must make valid parameters."""
    cfg = config["onedof"]["sweeps"][sweep]
    key = f"onedof.sweeps.{sweep}"
    baseline = config["onedof"]["baseline"]
    base = run_spec(
        config, cfg.get("scene") or baseline["scene"], reading, cfg.get("method") or baseline["method"]
    )
    dense_cfg = cfg["dense"]
    scale = dense_cfg.get("spacing") or "linear"
    spaced = np.geomspace if scale == "log" else np.linspace
    dense = spaced(float(dense_cfg["start"]), float(dense_cfg["stop"]), int(dense_cfg["num"]))
    linked = dict(cfg.get("linked") or {})
    axis = SweepAxis(cfg["parameter"], tuple(dense), linked=linked)
    for value in [*cfg["values"], dense[0], dense[-1]]:
        try:
            base.params.with_(**axis.point(value))
        except ParameterError as exc:
            raise ParameterError(f"{key}.values ({cfg['parameter']} = {value:g}): {exc}") from None
    return SweepSpec(
        name=sweep,
        figure=str(cfg.get("figure") or ""),
        parameter=cfg["parameter"],
        values=tuple(float(v) for v in cfg["values"]),
        dense=tuple(float(v) for v in dense),
        linked=linked,
        units=str(cfg.get("units") or "1"),
        long_name=str(cfg.get("long_name") or cfg["parameter"]),
        base=base,
        coord_scale=scale,
        law=_law(cfg, key),
    )


# --- dense maps ---------------------------------------------------------------------------------------------

DEFAULT_PLOT = ("amplitude_peak_to_peak", "frequency_peaks", "stick_fraction")


def axis_values(axis: dict) -> tuple[float, ...]:
    """An axis's values: listed, or ``num`` points from ``start`` to ``stop`` (``spacing`` linear or log)."""
    if axis.get("values") is not None:
        return tuple(float(v) for v in axis["values"])
    spaced = np.geomspace if axis.get("spacing") == "log" else np.linspace
    return tuple(float(v) for v in spaced(axis["start"], axis["stop"], axis["num"]))


def sweep_axis(axis: dict) -> SweepAxis:
    return SweepAxis(
        axis["name"],
        axis_values(axis),
        str(axis.get("units") or ""),
        str(axis.get("long_name") or ""),
        dict(axis.get("linked") or {}),
    )


@dataclass(frozen=True)
class DenseMap:
    name: str
    spec: RunSpec
    """Base run: scene parameters, reading (friction variant, sigma), solver and run lengths."""
    axes: list[SweepAxis]
    chunk_size: int
    chunks: int
    title: str
    plot: tuple
    law: FrictionLaw | None = None
    """Any friction law replacing the reading's (solved with the switch solver); None: the reading's law."""

    @property
    def points(self) -> int:
        return grid_size(self.axes)

    def run(self, points: list[dict], progress=None) -> dict:
        """Metric arrays of the given grid points with this map's base run (run_points)."""
        s = self.spec
        return run_points(
            s.params,
            s.variant,
            points,
            s.solver(),
            s.t_end,
            s.t_eval,
            s.transient,
            s.count_window,
            progress=progress,
            law=self.law,
        )

    def method_attrs(self) -> dict:
        return {
            "name": self.spec.method,
            **self.spec.solver_settings,
            "chunk_size": self.chunk_size,
            "chunks": self.chunks,
            "grid_points": self.points,
            "t_end": self.spec.t_end,
            "output_dt": self.spec.output_dt,
            "transient": self.spec.transient,
            "count_window": self.spec.count_window,
        }

    def scene_attrs(self) -> dict:
        base = self.spec.scene_attrs()
        for axis in self.axes:  # a swept parameter's base value is not used: point to the coordinate
            for name in (axis.name, *axis.linked):
                base[name] = f"swept (coordinate {axis.name})"
        if self.law is not None:
            base["friction_law"] = repr(self.law)
        return {
            **base,
            "map": self.name,
            "swept": ", ".join(
                f"{a.name} ({len(a.values)} values, {min(a.values):g}..{max(a.values):g})" for a in self.axes
            ),
        }


def dense_map(config: dict, name: str) -> DenseMap:
    """``dense_map.maps.<name>``: its base run and axes; both ends of every axis make valid parameters."""
    section = config["dense_map"]
    cfg = section["maps"][name]
    key = f"dense_map.maps.{name}"
    try:
        spec = run_spec(config, cfg["scene"], cfg["reading"], cfg["method"])
    except ParameterError as exc:
        raise ParameterError(f"{key} (scene/reading/method): {exc}") from None
    spec = dataclasses.replace(spec, **{k: float(cfg[k]) for k in RUN_LENGTHS if cfg.get(k) is not None})
    axes = [sweep_axis(a) for a in cfg["axes"]]
    for i, axis in enumerate(axes):
        for value in (min(axis.values), max(axis.values)):
            try:
                spec.params.with_(**axis.point(value))
            except ParameterError as exc:
                raise ParameterError(f"{key}.axes[{i}] ({axis.name} = {value:g}): {exc}") from None
    chunk_size = cfg.get("chunk_size") or section["chunk_size"]
    return DenseMap(
        name=name,
        spec=spec,
        axes=axes,
        chunk_size=chunk_size,
        chunks=chunk_count(axes, chunk_size),
        title=str(cfg.get("title") or name),
        plot=tuple(cfg.get("plot") or DEFAULT_PLOT),
        law=_law(cfg, key),
    )
