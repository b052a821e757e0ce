"""From the validated config to run specifications: scene x reading x method, a sweep, a dense map.

Each function takes the typed section it reads (``stickslip.schema``: ``Onedof``, or a job's part of it,
``OnedofRuns``), checked before anything here runs (``stickslip.pipeline.config.validate_config``: types,
bounds, references between sections, which solver a friction law needs). What is left is resolution:
merge defaults, scene, reading and method into a ``RunSpec`` and build the science objects
(``BeltParams``, the solver, a friction law), whose constructors check physics; their errors are re-keyed
to the config path they came from, so ``validate_config`` (which resolves every run at parse time) names it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TypeVar

import numpy as np

from ..analysis.metrics import PAPER_COUNT_WINDOW
from ..analysis.sweep import SweepAxis, chunk_count, grid_size, run_points
from ..model.equations import BeltModel
from ..model.laws import FrictionLaw, LawModel, law_from_config
from ..model.params import BeltParams, ParameterError
from ..schema import (
    DenseMapJob,
    DenseMaps,
    DenseRange,
    Figure,
    Law,
    MapAxis,
    OnedofJob,
    OnedofRuns,
    merged_run_lengths,
    scene_run_lengths,
)
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

#: Keys a reading may set on top of a scene's parameters (which sigma, which units, a friction plateau).
READING_PARAMS = ("sigma", "units", "plateau_speed")

T = TypeVar("T")

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
        return self.model.slip_friction if self.law is not None else self.model.friction

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

    def write(self, ds, path: str, title: str, scene: Mapping = {}, method: Mapping = {}) -> None:
        """Write a dataset of this run, its scene, reading and method (with ``scene``/``method`` added) as
        provenance."""
        from ..io.netcdf import write_dataset

        write_dataset(
            ds,
            path,
            scene=self.scene_attrs() | dict(scene),
            interpretation=self.interpretation(),
            method={"name": self.method, **self.solver_settings, **method},
            title=title,
        )


def from_job_params(build: Callable[[OnedofRuns], T]) -> Callable[[Mapping], T]:
    """``build`` of the typed section as a function of a job's params mapping (``OnedofJob``): the mapping
    the perturbation ensemble perturbs, typed once per member."""
    return lambda params: build(OnedofJob.model_validate(params).onedof)


def job_dataset(
    build: Callable[[OnedofRuns], T], config: Mapping, ensemble: Mapping | None, path: str, claimed=True
):
    """``build`` of a 1-DOF job's params mapping ``config``, with the perturbation ensemble of the config's
    ``ensemble`` section when the dataset ``path`` is ``claimed`` (a 1-DOF run sets no BLAS threads)."""
    from ..ensemble import EnsembleSpec, ensemble_dataset

    members = EnsembleSpec.from_mapping(ensemble).without_blas() if claimed else None
    return ensemble_dataset(from_job_params(build), config, members, run_id=path, fields=PERTURBED_FIELDS)


def run_spec(onedof: OnedofRuns, scene: str, reading: str, method: str) -> RunSpec:
    """Scene parameters over the defaults, the reading's interpretation over them, and the method."""
    defaults, scene_cfg = onedof.defaults, onedof.scenes[scene]
    reading_cfg, method_cfg = onedof.readings[reading], onedof.methods[method]
    params = defaults.params.model_dump(exclude_none=True)
    params |= scene_cfg.params.model_dump(exclude_none=True) if scene_cfg.params else {}
    params |= reading_cfg.model_dump(include=set(READING_PARAMS), exclude_none=True)
    try:
        belt = BeltParams(**params)
    except ParameterError as exc:
        raise ParameterError(f"onedof.scenes.{scene}.params.{exc}") from None
    run, _ = scene_run_lengths(onedof, scene, reading)
    spec = RunSpec(
        scene=scene,
        reading=reading,
        method=method,
        params=belt,
        variant=reading_cfg.variant,
        t_end=float(run["t_end"]),
        output_dt=float(run["output_dt"]),
        transient=float(run.get("transient", 0.0)),
        count_window=float(run.get("count_window", PAPER_COUNT_WINDOW)),
        # sorted: a dataset's method attributes do not depend on the order the config lists the settings in
        solver_settings=dict(sorted(method_cfg.model_dump(exclude_none=True).items())),
        figure=scene_cfg.figure,
        description=scene_cfg.description,
        law=_law(scene_cfg.law, f"onedof.scenes.{scene}"),
    )
    spec.solver()  # the solver checks its settings at construction: fail now, naming the method
    if spec.law is not None and method_cfg.solver != "switch":
        raise ParameterError(
            f"onedof.scenes.{scene}.law: a {spec.law.kind!r} friction law is solved by the 'switch' solver "
            f"only; method {method!r} uses {method_cfg.solver!r}"
        )
    return spec


def baseline_spec(onedof: OnedofRuns, reading: str | None = None) -> RunSpec:
    """The paper's baseline run (``onedof.baseline``), under its own reading or ``reading``."""
    base = onedof.baseline
    return run_spec(onedof, base.scene, reading or base.reading, base.method)


def figure_runs(figure: Figure) -> list[tuple[str, str, str]]:
    """(scene, reading, method) triples a figure needs."""
    return [(figure.scene, r, m) for r in figure.readings for m in figure.methods]


def _law(law: Law | None, key: str) -> FrictionLaw | None:
    return law_from_config(law.model_dump(), key=f"{key}.law") if law is not None else None


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


def sweep_spec(onedof: OnedofRuns, sweep: str, reading: str) -> SweepSpec:
    """``onedof.sweeps.<sweep>`` for one reading; every point must make valid parameters."""
    cfg = onedof.sweeps[sweep]
    key = f"onedof.sweeps.{sweep}"
    baseline = onedof.baseline
    base = run_spec(onedof, cfg.scene or baseline.scene, reading, cfg.method or baseline.method)
    dense = axis_values(cfg.dense)
    axis = SweepAxis(cfg.parameter, dense, linked=cfg.linked)
    check_points(base.params, axis, [*cfg.values, dense[0], dense[-1]], f"{key}.values")
    return SweepSpec(
        name=sweep,
        figure=cfg.figure,
        parameter=cfg.parameter,
        values=tuple(cfg.values),
        dense=dense,
        linked=dict(cfg.linked),
        units=cfg.units,
        long_name=cfg.long_name or cfg.parameter,
        base=base,
        coord_scale=cfg.dense.spacing,
        law=_law(cfg.law, key),
    )


def check_points(params: BeltParams, axis: SweepAxis, values, key: str) -> None:
    """Each of ``values`` on ``axis`` makes valid parameters; an error names ``key`` and the value."""
    for value in values:
        try:
            params.with_(**axis.point(value))
        except ParameterError as exc:
            raise ParameterError(f"{key} ({axis.name} = {value:g}): {exc}") from None


# --- dense maps ---------------------------------------------------------------------------------------------


def axis_values(axis: MapAxis | DenseRange) -> tuple[float, ...]:
    """An axis's values: listed, or ``num`` points from ``start`` to ``stop`` (``spacing`` linear or log)."""
    if getattr(axis, "values", None) is not None:
        return tuple(float(v) for v in axis.values)
    spaced = np.geomspace if axis.spacing == "log" else np.linspace
    return tuple(float(v) for v in spaced(axis.start, axis.stop, axis.num))


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


def dense_map(onedof: OnedofRuns, maps: DenseMaps, name: str) -> DenseMap:
    """``dense_map.maps.<name>``: its base run and axes; both ends of every axis make valid parameters."""
    cfg = maps.maps[name]
    key = f"dense_map.maps.{name}"
    try:
        spec = run_spec(onedof, cfg.scene, cfg.reading, cfg.method)
    except ParameterError as exc:
        raise ParameterError(f"{key} (scene/reading/method): {exc}") from None
    lengths, _ = merged_run_lengths([(key, cfg)])  # the map's own run lengths, over the scene's
    spec = dataclasses.replace(spec, **{k: float(v) for k, v in lengths.items()})
    axes = [SweepAxis(a.name, axis_values(a), a.units, a.long_name, dict(a.linked)) for a in cfg.axes]
    for i, axis in enumerate(axes):
        check_points(spec.params, axis, (min(axis.values), max(axis.values)), f"{key}.axes[{i}]")
    chunk_size = cfg.chunk_size or maps.chunk_size
    return DenseMap(
        name=name,
        spec=spec,
        axes=axes,
        chunk_size=chunk_size,
        chunks=chunk_count(axes, chunk_size),
        title=cfg.title or name,
        plot=tuple(cfg.plot),
        law=_law(cfg.law, key),
    )


def dense_map_job(params: Mapping, name: str) -> DenseMap:
    """The map a dense-map job's params hold (``DenseMapJob``), resolved as its jobs resolve it."""
    job = DenseMapJob.model_validate(params)
    return dense_map(job.onedof, job.dense_map, name)
