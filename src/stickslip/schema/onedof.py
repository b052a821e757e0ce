"""The sections of ``config/config.yaml``: the 1-DOF mass on belt (``onedof``), ``claims``, ``ensemble``
and ``notebooks``."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from ..model.params import BeltParams
from .base import (
    Finite,
    Names,
    NonNegative,
    Open,
    Positive,
    Section,
    Units,
    Variant,
    belt_parameter,
    check_refs,
    linked_parameters,
    needs_switch,
    parameter_section,
)

#: A scene's 1-DOF parameters: BeltParams's keys, types and bounds, each optional.
BeltParameters = parameter_section("BeltParameters", BeltParams.__pydantic_fields__)


class RunLengths(Section):
    t_end: Positive | None = Field(None, description="simulated time [s]")
    output_dt: Positive | None = Field(None, description="output interval [s]")
    transient: NonNegative | None = Field(None, description="discarded start [s]")
    count_window: Positive | None = Field(None, description="peak-count window [s] (paper: 18 s)")


def check_run_lengths(run: dict, key_of: dict) -> None:
    """A run's lengths fit inside it: ``output_dt <= t_end``, ``transient < t_end``, ``count_window <=
    t_end`` (peaks are counted in [0, count_window]). ``key_of`` names where each value came from."""
    t_end = run.get("t_end")
    if t_end is None:
        return
    for name, bad in (
        ("output_dt", lambda v: v > t_end),
        ("transient", lambda v: v >= t_end),
        ("count_window", lambda v: v > t_end),
    ):
        value = run.get(name)
        if value is not None and bad(value):
            raise ValueError(
                f"{key_of[name]}: {value!r} does not fit in the run's t_end = {t_end!r} ({key_of['t_end']})"
            )


def merged_run_lengths(layers: list[tuple[str, Any]]) -> tuple[dict, dict]:
    """(values, key each came from) of the run-length keys over config layers, later layers winning."""
    run, key_of = {}, {}
    for prefix, layer in layers:
        for name in ("t_end", "output_dt", "transient", "count_window"):
            value = getattr(layer, name, None) if layer is not None else None
            if value is not None:
                run[name], key_of[name] = value, f"{prefix}.{name}"
    return run, key_of


class OnedofDefaults(RunLengths):
    params: BeltParameters
    t_end: Positive
    output_dt: Positive


class Reading(Section):
    variant: Variant
    sigma: NonNegative | None = None
    units: Units | None = None
    plateau_speed: Positive | None = None
    output_dt: Positive | None = None
    description: str | None = None


class Method(Open):
    solver: str
    rtol: Positive | None = None
    atol: Positive | None = None

    @field_validator("solver")
    @classmethod
    def registered(cls, name: str) -> str:
        from ..solvers import REGISTRY  # the registry is the one list of solver names

        if name not in REGISTRY:
            raise ValueError(f"{name!r} is not one of {sorted(REGISTRY)}")
        return name


class Scene(RunLengths):
    figure: str = ""
    description: str = ""
    params: BeltParameters | None = None
    law: Law | None = None  # any friction law replacing the reading's (as in sweeps; switch solver only)


#: The paper figures a figure of the pipeline shows (the catalogue's ``figures`` of its runs' entries); none
#: for a figure of one's own scene.
PaperFigures = list[Annotated[int, Field(ge=1, le=36, description="a figure of the paper (1-36)")]]


class Eq6(Section):
    paper_figures: PaperFigures = []
    f_max: Positive
    points: Annotated[int, Field(ge=10)]
    force: str = Field("mu_s N", description="what the friction force F of Eq. 6 is taken to be")


class Law(Open):
    """Any friction law of ``model/laws.py``: ``kind`` and its parameters (checked by ``law_from_config``)."""

    kind: Literal["affine", "coulomb", "stribeck", "rational", "tabulated"]


class DenseRange(Section):
    start: Finite
    stop: Finite
    num: Annotated[int, Field(ge=2)]
    spacing: Literal["linear", "log"] = "linear"  # the same key as a dense map's axis

    @model_validator(mode="after")
    def ordered(self):
        if self.start >= self.stop:
            raise ValueError(f"start < stop needed, got {self.start!r} >= {self.stop!r}")
        if self.spacing == "log" and self.start <= 0:
            raise ValueError(f"log spacing needs start > 0, got {self.start!r}")
        return self


class Sweep(Section):
    figure: str = ""
    scene: str | None = None
    method: str | None = None
    parameter: str
    units: str = "1"
    long_name: str | None = Field(None, description="default: the parameter's name")
    values: Annotated[list[Finite], Field(min_length=1)]
    linked: dict[str, Finite] = Field({}, description="parameters set to factor x the swept value")
    law: Law | None = None
    dense: DenseRange

    _parameter = field_validator("parameter")(belt_parameter)
    _linked = field_validator("linked")(linked_parameters)


class SweepFigure(Section):
    title: str | None = None
    paper_figures: PaperFigures = []
    sweep: str
    readings: Names


class CriticalSpeed(Section):
    readings: Names
    start: Positive
    stop: Positive
    num: Annotated[int, Field(ge=3)]
    t_end: Positive
    transient: NonNegative

    @model_validator(mode="after")
    def ordered(self):
        if not self.start < self.stop:
            raise ValueError(
                f"start < stop needed (the continuation runs upward), got {self.start!r}, {self.stop!r}"
            )
        if not self.transient < self.t_end:
            raise ValueError(f"transient: {self.transient!r} does not fit in t_end = {self.t_end!r}")
        return self


class FrictionTable(Section):
    scene: str
    reading: str
    method: str
    bins: Annotated[int, Field(ge=2)]


class Figure(Section):
    title: str | None = None
    paper_figures: PaperFigures = []
    scene: str
    plot: Literal["timeseries", "phase", "velocity"] = "timeseries"
    readings: Names
    methods: Names


class Baseline(Section):
    """The paper's baseline run: what a study without its own scene, reading or method starts from."""

    scene: str
    reading: str
    method: str


class OnedofRuns(Section):
    """What a 1-DOF job reads (its params, ``onedof_subconfig``): the baseline, the defaults, some readings,
    methods and scenes and a study's section. A part of the section, so names referring to entries left out
    are not checked here: the whole section (``Onedof``) was checked at parse time."""

    baseline: Baseline
    defaults: OnedofDefaults
    readings: Annotated[dict[str, Reading], Field(min_length=1)]
    methods: Annotated[dict[str, Method], Field(min_length=1)]
    scenes: Annotated[dict[str, Scene], Field(min_length=1)]
    eq6: Eq6 | None = None
    sweeps: dict[str, Sweep] = {}
    critical_speed: CriticalSpeed | None = None
    friction_table: FrictionTable | None = None


def scene_run_lengths(onedof: OnedofRuns, scene: str, reading: str) -> tuple[dict, dict]:
    """(values, key each came from) of a scene's run under a reading: the defaults, then the scene's own,
    then the reading's ``output_dt``."""
    layers = [
        (f"onedof.scenes.{scene}", onedof.scenes[scene]),
        (f"onedof.readings.{reading}", onedof.readings[reading]),
    ]
    return merged_run_lengths([("onedof.defaults", onedof.defaults), *layers])


class OnedofJob(Section):
    """A 1-DOF job's params mapping (``{"onedof": ...}``), the mapping the perturbation ensemble perturbs."""

    onedof: OnedofRuns


class Onedof(OnedofRuns):
    sweep_figures: dict[str, SweepFigure] = {}
    friction_table: FrictionTable
    figures: dict[str, Figure]

    @model_validator(mode="after")
    def names_refer_to_entries(self):
        """Figures, sweeps, sweep figures, the friction table and the critical speed name existing
        scenes, readings, methods and sweeps."""
        scenes, readings, methods = [], [], []
        for name, fig in self.figures.items():
            scenes.append((f"onedof.figures.{name}.scene", fig.scene))
            readings += [(f"onedof.figures.{name}.readings", r) for r in fig.readings]
            methods += [(f"onedof.figures.{name}.methods", m) for m in fig.methods]
        base = self.baseline
        for key, run in (("onedof.baseline", base), ("onedof.friction_table", self.friction_table)):
            scenes.append((f"{key}.scene", run.scene))
            readings.append((f"{key}.reading", run.reading))
            methods.append((f"{key}.method", run.method))
        for name, sweep in self.sweeps.items():
            scenes.append((f"onedof.sweeps.{name}.scene", sweep.scene or base.scene))
            methods.append((f"onedof.sweeps.{name}.method", sweep.method or base.method))
        if self.critical_speed is not None:
            readings += [("onedof.critical_speed.readings", r) for r in self.critical_speed.readings]
        for name, fig in self.sweep_figures.items():
            check_refs([(f"onedof.sweep_figures.{name}.sweep", fig.sweep)], self.sweeps, "onedof.sweeps")
            readings += [(f"onedof.sweep_figures.{name}.readings", r) for r in fig.readings]
        check_refs(scenes, self.scenes, "onedof.scenes")
        check_refs(readings, self.readings, "onedof.readings")
        check_refs(methods, self.methods, "onedof.methods")
        for name, sweep in self.sweeps.items():
            needs_switch(f"onedof.sweeps.{name}", sweep.law, sweep.method or base.method, self.methods)
        for name, fig in self.figures.items():  # a scene with its own law runs only under the switch solver
            for method in fig.methods:
                needs_switch(f"onedof.figures.{name}", self.scenes[fig.scene].law, method, self.methods)
        for scene in self.scenes:
            for reading in self.readings:
                check_run_lengths(*scene_run_lengths(self, scene, reading))
        return self


class Claims(Section):
    readings: Names
    check: bool = Field(
        True, description="false: no pinned status is checked (a config that measures other numbers)"
    )
    #: the reading every figure's verdict is given in, declared by the rule of docs/READINGS.md
    primary_reading: str
    #: the equations and values exactly as printed, shown beside the primary verdict
    as_printed_reading: str
    #: the primary rule's other defensible application (docs/READINGS.md), its headline shown beside
    alternative_reading: str | None = None

    @model_validator(mode="after")
    def _verdict_readings_are_checked(self):
        for key in ("primary_reading", "as_printed_reading", "alternative_reading"):
            if getattr(self, key) is not None and getattr(self, key) not in self.readings:
                raise ValueError(
                    f"{key}: {getattr(self, key)!r} is not one of claims.readings {self.readings}"
                )
        return self


class Ensemble(Section):
    relative: Annotated[float, Field(gt=0, lt=1e-3, allow_inf_nan=False)] | None = None
    seeds: Annotated[list[int], Field(min_length=1)] | None = None
    step_factor: Annotated[float, Field(gt=0, lt=1, allow_inf_nan=False)] | None = None
    step_keys: list[str] | None = None
    blas_threads: Annotated[int, Field(ge=1)] | None = None
    window_factor: Annotated[float, Field(gt=1, le=2, allow_inf_nan=False)] | None = Field(
        None, description="a later measurement-window start (transient x factor) as one more member"
    )
    window_keys: list[str] | None = None


class Notebook(Section):
    figures: list[str] | None = None
    sweep_figures: list[str] | None = None
    inputs: list[str] | None = Field(
        None, description="{reading}: each claims reading; {critical_reading}: each critical-speed reading"
    )


class OnedofProject(BaseModel):
    """The sections of the project config that a 1-DOF run of your own (``stickslip.simulate``) and the
    command line read; the others are left to the whole config's check (which also resolves every FE scene
    and study: seconds a single run does not need)."""

    model_config = ConfigDict(extra="ignore", strict=True)

    onedof: Onedof
    claims: Claims
    ensemble: Ensemble | None = None
    allow_expensive: bool = False
