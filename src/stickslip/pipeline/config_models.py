"""The pipeline's configuration as typed models (pydantic v2): one model per config section.

Every mapping forbids unknown keys, every number must be finite (no NaN or inf), bounds are physical
(masses, stiffnesses, durations > 0), and an error names the full key (``onedof.scenes.fig02.params.mass``).
``stickslip.pipeline.config.validate_config`` validates the merged config against ``PipelineConfig`` and
then resolves what a model alone cannot (names that refer to other sections, solver settings, files).
The JSON schema in ``workflow/schemas/config.schema.json`` is generated from these models
(``python -m stickslip.pipeline.config_models --write``; a test checks it is current), never written by hand.

Every section is typed here, the inverse study's and the friction-law validation's included.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

#: Jobs a dense map may be split into unless ``dense_map.max_chunks`` says otherwise.
DEFAULT_MAX_CHUNKS = 2000

#: Where the generated JSON schema lives (for editors, `snakemake --lint` readers and documentation).
SCHEMA_PATH = Path("workflow/schemas/config.schema.json")

Finite = Annotated[float, Field(allow_inf_nan=False)]
Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]
NonNegative = Annotated[float, Field(ge=0, allow_inf_nan=False)]
Fraction = Annotated[float, Field(gt=0, le=1, allow_inf_nan=False)]
Names = Annotated[list[str], Field(min_length=1)]
#: A reading of the paper's friction law (``stickslip.model.friction.VARIANTS``; a test keeps them equal).
Variant = Literal["eq3_printed", "eq4_printed", "consistent"]
#: How the parameters' units are read (``stickslip.model.params.UNIT_READINGS``; a test keeps them equal).
Units = Literal["as_given", "si"]


def belt_parameter(name: str) -> str:
    """``name`` is a parameter of the 1-DOF model (what a sweep or a map axis may set)."""
    import dataclasses

    from ..model.params import BeltParams

    known = {f.name for f in dataclasses.fields(BeltParams)} - {"units"}
    if name not in known:
        raise ValueError(f"{name!r} is not a parameter (known: {sorted(known)})")
    return name


def linked_parameters(linked: dict | None) -> dict | None:
    for name in linked or {}:
        belt_parameter(name)
    return linked


def needs_switch(key: str, law, method: str, methods: dict) -> None:
    """A friction law other than the readings' is solved by the switch solver only."""
    if law is not None and methods[method].solver != "switch":
        raise ValueError(
            f"{key}.method: a friction law needs a method whose solver is 'switch' (the exact solver handles "
            f"the readings' affine laws only), got {method!r}"
        )


def check_refs(refs, known: dict, section: str) -> None:
    """Every (key, name) in ``refs`` names an entry of ``known`` (the mapping at ``section``)."""
    for key, name in refs:
        if name not in known:
            raise ValueError(f"{key}: {name!r} is not an entry of {section} ({sorted(known)})")


class Section(BaseModel):
    """A config mapping: unknown keys are errors (a misspelt key must not be silently ignored)."""

    model_config = ConfigDict(extra="forbid", strict=True)  # no "5" for 5: YAML types are meant


class Open(BaseModel):
    """A mapping whose extra keys are settings checked elsewhere (solver settings: ``check_settings``)."""

    model_config = ConfigDict(extra="allow", strict=True)


# -- 1-DOF mass on belt --------------------------------------------------------------------------------------


class BeltParameters(Section):
    mass: Positive | None = Field(None, description="M [kg]")
    stiffness: Positive | None = Field(None, description="K [N/mm]")
    damping: NonNegative | None = Field(None, description="C [N s/mm]")
    mu_s: Positive | None = Field(None, description="static friction coefficient")
    sigma: NonNegative | None = Field(None, description="friction slope [s/mm]")
    normal_force: Positive | None = Field(None, description="N [N]")
    x0: Finite | None = Field(None, description="initial displacement [mm]")
    v0: Finite | None = Field(None, description="initial velocity [mm/s]")
    belt_velocity: NonNegative | None = Field(None, description="V_b [mm/s]")
    belt_deceleration: NonNegative | None = Field(None, description="[mm/s^2]")
    units: Units | None = None
    plateau_speed: Positive | None = Field(None, description="friction plateau speed v_p [mm/s]")


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
    figure: str | None = None
    description: str | None = None
    params: BeltParameters | None = None
    law: Law | None = None  # any friction law replacing the reading's (as in sweeps; switch solver only)


class Eq6(Section):
    f_max: Positive
    points: Annotated[int, Field(ge=10)]
    force: str | None = None


class Law(Open):
    """Any friction law of ``model/laws.py``: ``kind`` and its parameters (checked by ``law_from_config``)."""

    kind: Literal["affine", "coulomb", "stribeck", "rational", "tabulated"]


class DenseRange(Section):
    start: Finite
    stop: Finite
    num: Annotated[int, Field(ge=2)]
    spacing: Literal["linear", "log"] | None = None  # the same key as a dense map's axis

    @model_validator(mode="after")
    def ordered(self):
        if self.start >= self.stop:
            raise ValueError(f"start < stop needed, got {self.start!r} >= {self.stop!r}")
        if self.spacing == "log" and self.start <= 0:
            raise ValueError(f"log spacing needs start > 0, got {self.start!r}")
        return self


class Sweep(Section):
    figure: str | None = None
    scene: str | None = None
    method: str | None = None
    parameter: str
    units: str | None = None
    long_name: str | None = None
    values: Annotated[list[Finite], Field(min_length=1)]
    linked: dict[str, Finite] | None = None
    law: Law | None = None
    dense: DenseRange

    _parameter = field_validator("parameter")(belt_parameter)
    _linked = field_validator("linked")(linked_parameters)


class SweepFigure(Section):
    title: str | None = None
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
    scene: str
    plot: Literal["timeseries", "phase", "velocity"] | None = None
    readings: Names
    methods: Names


class Baseline(Section):
    """The paper's baseline run: what a study without its own scene, reading or method starts from."""

    scene: str
    reading: str
    method: str


class Onedof(Section):
    baseline: Baseline
    defaults: OnedofDefaults
    readings: Annotated[dict[str, Reading], Field(min_length=1)]
    methods: Annotated[dict[str, Method], Field(min_length=1)]
    scenes: Annotated[dict[str, Scene], Field(min_length=1)]
    eq6: Eq6 | None = None
    sweeps: dict[str, Sweep] = {}
    sweep_figures: dict[str, SweepFigure] = {}
    critical_speed: CriticalSpeed | None = None
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
        scenes.append(("onedof.baseline.scene", base.scene))
        readings.append(("onedof.baseline.reading", base.reading))
        methods.append(("onedof.baseline.method", base.method))
        for name, sweep in self.sweeps.items():
            scenes.append((f"onedof.sweeps.{name}.scene", sweep.scene or base.scene))
            methods.append((f"onedof.sweeps.{name}.method", sweep.method or base.method))
        table = self.friction_table
        scenes.append(("onedof.friction_table.scene", table.scene))
        readings.append(("onedof.friction_table.reading", table.reading))
        methods.append(("onedof.friction_table.method", table.method))
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
        for name, scene in self.scenes.items():
            for rname, reading in self.readings.items():
                check_run_lengths(
                    *merged_run_lengths(
                        [
                            ("onedof.defaults", self.defaults),
                            (f"onedof.scenes.{name}", scene),
                            (f"onedof.readings.{rname}", reading),
                        ]
                    )
                )
        return self


class Claims(Section):
    readings: Names
    check: bool | None = None
    #: the reading every figure's verdict is given in, declared by the rule of docs/READINGS.md
    primary_reading: str
    #: the equations and values exactly as printed, shown beside the primary verdict
    as_printed_reading: str

    @model_validator(mode="after")
    def _verdict_readings_are_checked(self):
        for key in ("primary_reading", "as_printed_reading"):
            if getattr(self, key) not in self.readings:
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


class Notebook(Section):
    figures: list[str] | None = None
    sweep_figures: list[str] | None = None
    inputs: list[str] | None = Field(
        None, description="{reading}: each claims reading; {critical_reading}: each critical-speed reading"
    )


# -- dense maps ----------------------------------------------------------------------------------------------


class MapAxis(Section):
    """Values listed, or ``num`` points from ``start`` to ``stop`` (linear or log ``spacing``)."""

    name: str
    values: Annotated[list[Finite], Field(min_length=1)] | None = None
    start: Finite | None = None
    stop: Finite | None = None
    num: Annotated[int, Field(ge=1)] | None = None
    spacing: Literal["linear", "log"] | None = None
    units: str | None = None
    long_name: str | None = None
    linked: dict[str, Finite] | None = None

    _name = field_validator("name")(belt_parameter)
    _linked = field_validator("linked")(linked_parameters)

    @model_validator(mode="after")
    def values_or_range(self):
        if self.values is None:
            missing = [k for k in ("start", "stop", "num") if getattr(self, k) is None]
            if missing:
                raise ValueError(f"{missing[0]}: missing (give either values or start, stop, num)")
            if self.num > 1 and not self.start < self.stop:
                raise ValueError(f"start < stop needed, got {self.start!r}, {self.stop!r}")
            if self.spacing == "log" and not (self.start > 0 and self.stop > 0):
                raise ValueError(
                    f"log spacing needs start > 0 and stop > 0, got {self.start!r}, {self.stop!r}"
                )
        return self

    @property
    def size(self) -> int:
        return len(self.values) if self.values is not None else self.num


class DenseMapEntry(RunLengths):
    title: str | None = None
    scene: str
    reading: str
    method: str
    law: Law | None = None
    chunk_size: Annotated[int, Field(ge=1)] | None = None
    plot: Names | None = None
    axes: Annotated[list[MapAxis], Field(min_length=1)]

    @model_validator(mode="after")
    def each_parameter_once(self):
        names = [a.name for a in self.axes]
        for i, name in enumerate(names):
            if name in names[:i]:
                raise ValueError(f"axes[{i}].name: {name!r} is swept twice")
        return self


class Resources(Open):
    mem_mb: Annotated[int, Field(ge=1)] | None = None
    runtime: Annotated[int, Field(ge=1)] | None = None
    cpus_per_task: Annotated[int, Field(ge=1)] | None = None


class DenseMapResources(Section):
    dense_map_chunk: Resources | None = None
    dense_map_merge: Resources | None = None
    dense_map_figure: Resources | None = None


class DenseMaps(Section):
    chunk_size: Annotated[int, Field(ge=1)]
    max_chunks: Annotated[int, Field(ge=1)] | None = None
    maps: Annotated[dict[str, DenseMapEntry], Field(min_length=1)]
    resources: DenseMapResources

    @model_validator(mode="after")
    def chunks_within_limit(self):
        """A chunk size that would make more jobs than ``max_chunks`` (default 2000) is an error."""
        import math

        limit = self.max_chunks or DEFAULT_MAX_CHUNKS
        for name, m in self.maps.items():
            points = math.prod(a.size for a in m.axes)
            size = m.chunk_size or self.chunk_size
            key = f"dense_map.maps.{name}.chunk_size" if m.chunk_size else "dense_map.chunk_size"
            jobs = math.ceil(points / size)
            if jobs > limit:
                raise ValueError(
                    f"{key}: {size} points per chunk make {jobs} jobs for {points} points, more than "
                    f"max_chunks = {limit}; use at least {math.ceil(points / limit)} points per chunk"
                )
        return self


# -- methods study -------------------------------------------------------------------------------------------


class StudyMethod(Section):
    solver: Literal["exact", "sign_rk", "smooth", "karnopp", "moreau", "switch"]
    settings: dict[str, Any] | None = None
    sweep: dict[str, Annotated[list[Any], Field(min_length=1)]] | None = None
    atol_per_rtol: Positive | None = None


class Budget(Section):
    max_rhs: Annotated[int, Field(ge=1)]
    max_cpu: Positive


class Timing(Section):
    min_repeats: Annotated[int, Field(ge=1)]
    max_repeats: Annotated[int, Field(ge=1)]
    min_total_cpu: NonNegative
    slow_run: Positive = 1.0
    """A run taking longer than this [s of CPU] is timed once."""

    @model_validator(mode="after")
    def ordered(self):
        if self.min_repeats > self.max_repeats:
            raise ValueError(f"min_repeats {self.min_repeats!r} > max_repeats {self.max_repeats!r}")
        return self


class StudyScene(Section):
    variant: Variant
    params: BeltParameters | None = None


class FailureMap(Section):
    scene: str
    parameter: str
    values: Annotated[list[Finite], Field(min_length=1)]
    t_end: Positive
    methods: Annotated[list[StudyMethod], Field(min_length=1)]


class MethodsStudy(Section):
    base_params: BeltParameters
    t_end: Positive
    output_dt: Positive
    budget: Budget
    timing: Timing
    paper_method: StudyMethod
    scenes: Annotated[dict[str, StudyScene], Field(min_length=1)]
    methods: Annotated[list[StudyMethod], Field(min_length=1)]
    failure_map: FailureMap

    @model_validator(mode="after")
    def lengths_fit(self):
        check_run_lengths(*merged_run_lengths([("methods_study", self)]))
        return self


# -- beam on disc (FE) ---------------------------------------------------------------------------------------


class Beam(Section):
    length: Positive | None = Field(None, description="mm")
    thickness: Positive | None = Field(None, description="mm")
    width: Positive | None = Field(None, description="mm")
    youngs_modulus_gpa: Positive | None = None
    density_kg_m3: Positive | None = None
    poisson_ratio: Annotated[float, Field(ge=0, lt=0.5, allow_inf_nan=False)] | None = None
    gravity_m_s2: NonNegative | None = None
    n_elements: Annotated[int, Field(ge=1)] | None = None
    mass: Literal["lumped", "consistent"] | None = None
    rotary_inertia: bool | None = None


class Disc(Section):
    diameter: Positive | None = Field(None, description="mm")
    speed_rev_per_min: NonNegative | None = None
    surface_speed_mm_s: NonNegative | None = None
    direction: Literal["clockwise", "counterclockwise"] | None = None


Angle = Annotated[float, Field(ge=-80, le=80, allow_inf_nan=False)]


class Contact(Section):
    method: Literal["kinematic", "penalty", "fixed_normal"] | None = None
    angle_deg: Angle | None = None
    penalty_stiffness: Positive | None = Field(None, description="N mm-1")
    surface_offset: bool | None = None
    output_node: Literal["free_end_lower", "free_end_axis", "free_end_upper"] | None = None


class FeSolver(Section):
    t_end: Positive | None = Field(None, description="simulated time [s]")
    safety_factor: Fraction | None = None
    output_dt: Positive | None = Field(None, description="output interval [s]")
    initial_state: Literal["static", "drop", "undeformed"] | None = None
    mass_damping: NonNegative | None = Field(None, description="s-1")
    stiffness_damping: NonNegative | None = Field(None, description="s")


class FeOutput(Section):
    bin_width: Positive | None = Field(None, description="s")
    windows: list[Annotated[list[NonNegative], Field(min_length=2, max_length=2)]] | None = None

    @model_validator(mode="after")
    def windows_ordered(self):
        for i, (start, stop) in enumerate(self.windows or []):
            if not start < stop:
                raise ValueError(f"windows[{i}]: start < stop needed, got [{start!r}, {stop!r}]")
        return self


class FeScene(Section):
    description: str | None = None
    beam: Beam | None = None
    disc: Disc | None = None
    contact: Contact | None = None
    solver: FeSolver | None = None
    output: FeOutput | None = None


def fe_scene_parameter(path: str) -> str:
    """A sweep's ``parameter``: ``<section>.<key>`` naming a numeric key of an FE scene's schema."""
    sections = {"beam": Beam, "disc": Disc, "contact": Contact, "solver": FeSolver}
    section, _, key = path.partition(".")
    if section not in sections:
        raise ValueError(f"{path!r}: the section must be one of {sorted(sections)}")
    numeric = sorted(
        name
        for name, field in sections[section].model_fields.items()
        if any(t in str(field.annotation) for t in ("float", "int")) and "bool" not in str(field.annotation)
    )
    if key not in numeric:
        raise ValueError(f"{path!r}: {section} has no numeric key {key!r} (it has {', '.join(numeric)})")
    return path


#: A friction slope d mu / d v_r [s mm-1] of the stability study: |slope| x 0.5 mm/s (the slowest disc
#: surface speed of the paper's scenes) at most 1, i.e. the friction coefficient changes by at most 1 over
#: that speed; the paper's own slopes (sigma = 0.3, 0.5) and the study's (<= 0.3) are far inside.
MAX_FRICTION_SLOPE = 2.0
Slope = Annotated[float, Field(ge=-MAX_FRICTION_SLOPE, le=MAX_FRICTION_SLOPE, allow_inf_nan=False)]


class FeSweep(Section):
    base: str
    parameter: str
    coord: str
    units: str | None = None
    long_name: str | None = None
    values: Annotated[list[Finite], Field(min_length=2)]
    t_end: Positive | None = None

    _parameter = field_validator("parameter")(fe_scene_parameter)


class Convergence(Section):
    base: str
    n_elements: Annotated[list[Annotated[int, Field(ge=1)]], Field(min_length=2)]
    safety_factors: Annotated[list[Fraction], Field(min_length=1)] | None = None
    t_end: Positive


class Stability(Section):
    base: str
    angles: Annotated[list[Angle], Field(min_length=1)]
    slopes: Annotated[list[Slope], Field(min_length=1)]
    crosscheck: list[Annotated[list[Finite], Field(min_length=2, max_length=2)]] | None = None
    crosscheck_e_folds: Positive | None = None
    crosscheck_max_t_end: Positive | None = None

    @model_validator(mode="after")
    def crosscheck_slopes_bounded(self):
        for i, (_, slope) in enumerate(self.crosscheck or []):
            if abs(slope) > MAX_FRICTION_SLOPE:
                raise ValueError(
                    f"crosscheck[{i}][1]: friction slope {slope!r} outside [-{MAX_FRICTION_SLOPE}, "
                    f"{MAX_FRICTION_SLOPE}] s mm-1"
                )
        return self


class Reduced(Section):
    n_bending_modes: Annotated[int, Field(ge=0)] | None = None
    n_axial_modes: Annotated[int, Field(ge=0)] | None = None
    safety_factor: Fraction | None = None


Mesh = Annotated[list[Annotated[int, Field(ge=1)]], Field(min_length=2, max_length=2)]


class Comparison(Section):
    mesh: Mesh
    t_end: Positive
    notes: dict[str, str] | None = None
    claim_windows: dict[str, Positive] | None = Field(
        None, description="scene -> t_end [s]: the continuum also runs these over a claim window (dt, dt/2)"
    )


class Increments(Section):
    base: str
    meshes: Annotated[list[Mesh], Field(min_length=1)]
    safety_factors: Annotated[list[Fraction], Field(min_length=1)]
    betas: Annotated[list[NonNegative], Field(min_length=1)]


class FePeer(Section):
    """The CalculiX peer of the continuum strip (rule fe_peer_calculix)."""

    mesh: Mesh = Field(
        description="nx, ny of the strip both the continuum and CalculiX solve (the paper's 100 x 1)"
    )
    tolerance: Fraction = Field(
        description="largest |relative difference| of any two of closed form, continuum, ccx"
    )


class LongRuns(Section):
    scene_t_end: Positive
    comparison_t_end: Positive


class Fe(Section):
    friction_table: str = Field(description="CSV relative_velocity_mm_per_s,mu from rule friction_table")
    long_runs: LongRuns
    control_readings_t_end: Positive = Field(
        description="solver.t_end [s] of every FE reading but the first (the default runs the scenes' own)"
    )
    defaults: FeScene
    readings: Annotated[dict[str, FeScene], Field(min_length=1)]
    scenes: Annotated[dict[str, FeScene], Field(min_length=1)]
    sweeps: dict[str, FeSweep]
    convergence: Convergence
    stability: Stability
    cross_scene: dict[str, Annotated[list[str], Field(min_length=3, max_length=3)]]
    reduced: Reduced
    comparison: Comparison
    increments: Increments
    peer: FePeer | None = None

    @model_validator(mode="after")
    def bases_are_scenes(self):
        refs = [(f"fe.sweeps.{n}.base", sw.base) for n, sw in self.sweeps.items()]
        refs += [(f"fe.{k}.base", getattr(self, k).base) for k in ("convergence", "stability", "increments")]
        refs += [(f"fe.cross_scene.{n}", s) for n, triple in self.cross_scene.items() for s in triple[:2]]
        refs += [(f"fe.comparison.claim_windows.{n}", n) for n in self.comparison.claim_windows or {}]
        check_refs(refs, self.scenes, "fe.scenes")
        return self


# -- inverse study -------------------------------------------------------------------------------------------

#: Parameters the inverse study may free (``stickslip.inverse.problem.PARAMS``; a test keeps them equal).
InverseParameter = Literal["sigma", "damping", "mu_s", "normal_force", "stiffness", "mass", "plateau_speed"]


class Bound(Section):
    min: Positive
    max: Positive
    reason: Annotated[str, Field(min_length=1)]

    @model_validator(mode="after")
    def ordered(self):
        if not self.min < self.max:
            raise ValueError(f"need min < max, got {self.min!r}, {self.max!r}")
        return self


class Family(Section):
    variant: Variant
    free: Annotated[list[InverseParameter], Field(min_length=1)]


class InverseFigure(Section):
    title: str | None = None
    scene: str | None = None
    sweep: str | None = None
    claims: Names

    @model_validator(mode="after")
    def scene_or_sweep(self):
        if (self.scene is None) == (self.sweep is None):
            raise ValueError("give exactly one of scene (an onedof scene) or sweep (an onedof sweep)")
        return self


class MuKRatio(Section):
    min: Positive
    max: Positive

    @model_validator(mode="after")
    def ordered(self):
        if not self.min < self.max:
            raise ValueError(f"need min < max, got {self.min!r}, {self.max!r}")
        return self


class Hypothesis(Section):
    """Values applied to every run of the joint problem (every other parameter as stated)."""

    description: Annotated[str, Field(min_length=1)]
    sigma: NonNegative | None = None
    units: Units | None = None
    output_dt: Positive | None = None
    eq4_term: bool | None = None
    mu_k_ratio: MuKRatio | None = None


class InverseSettings(Section):
    starts: Annotated[int, Field(ge=1)]
    max_nfev: Annotated[int, Field(ge=1)]
    walkers: Annotated[int, Field(ge=2)]
    steps: Annotated[int, Field(ge=1)]
    joint_steps: Annotated[int, Field(ge=0)] = Field(description="0: the joint region is the Laplace one")
    scan_points: Annotated[int, Field(ge=2)]
    loo: Literal["linear", "refit"]
    loo_nfev: Annotated[int, Field(ge=1)] | None = None
    corner: list[str] = []
    seed: int


class Inverse(Section):
    long: bool = False
    claims_glob: str
    families: Annotated[dict[str, Family], Field(min_length=1)]
    stated: dict[str, Finite] | None = None
    bounds: dict[InverseParameter, Bound]
    constraints: dict[str, str] | None = None
    figures: Annotated[dict[str, InverseFigure], Field(min_length=1)]
    joint: Names
    hypotheses: dict[str, Hypothesis] = {}
    settings: dict[Literal["default", "long"], InverseSettings]

    @model_validator(mode="after")
    def complete_and_consistent(self):
        missing = [p for p in InverseParameter.__args__ if p not in self.bounds]
        if missing:
            raise ValueError(f"bounds.{missing[0]}: missing (every parameter a family may free needs bounds)")
        for mode in ("default", "long"):
            if mode not in self.settings:
                raise ValueError(f"settings.{mode}: missing")
            corner = [(f"inverse.settings.{mode}.corner", f) for f in self.settings[mode].corner]
            check_refs([c for c in corner if c[1] != "joint"], self.figures, "inverse.figures")
        check_refs([("inverse.joint", f) for f in self.joint], self.figures, "inverse.figures")
        return self


# -- friction-law validation ---------------------------------------------------------------------------------


class Tolerance(Section):
    abs: Positive
    reason: Annotated[str, Field(min_length=1)]


class ValidationTolerances(Section):
    time: Tolerance
    position: Tolerance
    closed_form: Tolerance


class SwitchSettings(Open):
    """Settings of the switch solver (others are checked by ``SwitchSolver`` at construction)."""

    rtol: Positive | None = None
    atol: Positive | None = None


class Peer(Section):
    program: str
    method: Literal["Adams", "BDF"]
    rtol: Positive
    atol: Positive


class ValidationLaw(Section):
    description: str | None = None
    law: Law
    params: BeltParameters | None = None
    closed_form: bool | None = None


class RoundTrip(Section):
    extension_factor: Annotated[float, Field(gt=1, allow_inf_nan=False)]
    curved_law: Law
    bins: Annotated[list[Annotated[int, Field(ge=2)]], Field(min_length=1)]
    curved_solver: SwitchSettings | None = None


class LawTiming(Timing):
    max_rhs: Annotated[int, Field(ge=1)]
    max_cpu: Positive


class MethodsPerLaw(Section):
    laws: list[str]
    t_end: Positive
    output_dt: Positive
    timing: LawTiming
    methods: Annotated[list[StudyMethod], Field(min_length=1)]
    paper_method: str

    @model_validator(mode="after")
    def lengths_fit(self):
        check_run_lengths(*merged_run_lengths([("validation.methods_per_law", self)]))
        return self


class Validation(Section):
    base_params: BeltParameters
    t_end: Positive
    solver: SwitchSettings
    peer: Peer
    tolerances: ValidationTolerances
    laws: Annotated[dict[str, ValidationLaw], Field(min_length=1)]
    round_trip: RoundTrip
    methods_per_law: MethodsPerLaw

    @model_validator(mode="after")
    def laws_exist(self):
        refs = [("validation.methods_per_law.laws", name) for name in self.methods_per_law.laws]
        check_refs(refs, self.laws, "validation.laws")
        return self


# -- the whole config ----------------------------------------------------------------------------------------

#: What one build may ask for before ``allow_expensive: true`` must say it is meant. The default config's
#: largest study stores 6.4e6 samples (the speed-damping dense map) and one run at most 4.0e4
#: (``estimated_costs``); the limits sit ~50-80x above, below what would exhaust a 24 GiB machine (8 bytes a
#: sample, several arrays a run).
MAX_SAMPLES_PER_RUN = 2_000_000
MAX_SAMPLES_PER_STUDY = 500_000_000
#: Largest beam mesh (elements) or continuum mesh (cells) without ``allow_expensive`` (the paper: 100 x 1).
MAX_FE_ELEMENTS = 20_000


def _samples(t_end: float, output_dt: float) -> int:
    return int(t_end / output_dt) + 1


def estimated_costs(cfg: PipelineConfig) -> list[tuple[str, str, float, float]]:
    """(key, what, estimate, limit) of every study whose size the config sets, in stored samples (1-DOF) or
    mesh elements (FE). Cheap: sizes only, nothing is allocated."""
    import math

    onedof = cfg.onedof
    out = []
    for name, scene in onedof.scenes.items():
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene)])
        for rname, reading in onedof.readings.items():
            dt = reading.output_dt or run["output_dt"]
            key = f"onedof.scenes.{name} (reading {rname})"
            out.append((key, "samples per run", _samples(run["t_end"], dt), MAX_SAMPLES_PER_RUN))
    for name, sweep in onedof.sweeps.items():
        scene = onedof.scenes.get(sweep.scene or onedof.baseline.scene)
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene)])
        points = (len(sweep.values) + sweep.dense.num) * len(cfg.claims.readings)
        per_run = _samples(run["t_end"], run["output_dt"])
        out.append((f"onedof.sweeps.{name}.dense.num", "samples", points * per_run, MAX_SAMPLES_PER_STUDY))
    for name, m in cfg.dense_map.maps.items():
        scene = onedof.scenes.get(m.scene)
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene), ("m", m)])
        points = math.prod(a.size for a in m.axes)
        per_run = _samples(run["t_end"], run["output_dt"])
        out.append((f"dense_map.maps.{name}.axes", "samples", points * per_run, MAX_SAMPLES_PER_STUDY))
    if onedof.critical_speed is not None:
        cs = onedof.critical_speed
        per_run = _samples(cs.t_end, onedof.defaults.output_dt)
        out.append(("onedof.critical_speed.num", "samples", cs.num * per_run, MAX_SAMPLES_PER_STUDY))
    fe = cfg.fe
    beams = [("fe.defaults", fe.defaults.beam)]
    beams += [
        (f"fe.{section}.{n}", sc.beam)
        for section in ("scenes", "readings")
        for n, sc in getattr(fe, section).items()
    ]
    for key, beam in beams:
        if beam is not None and beam.n_elements is not None:
            out.append((f"{key}.beam.n_elements", "elements", beam.n_elements, MAX_FE_ELEMENTS))
    out.append(("fe.convergence.n_elements", "elements", max(fe.convergence.n_elements), MAX_FE_ELEMENTS))
    for i, (nx, ny) in enumerate([fe.comparison.mesh] + list(fe.increments.meshes)):
        key = "fe.comparison.mesh" if i == 0 else f"fe.increments.meshes[{i - 1}]"
        out.append((key, "cells", nx * ny, MAX_FE_ELEMENTS))
    return out


class PipelineConfig(Section):
    """The merged config Snakemake builds from config/*.yaml (and any --configfile)."""

    onedof: Onedof
    claims: Claims
    notebooks: dict[str, Notebook]
    ensemble: Ensemble | None = None
    dense_map: DenseMaps
    methods_study: MethodsStudy
    fe: Fe
    fe_long_runs: bool = Field(False, description="run the paper's windows (fe.long_runs), not short ones")
    inverse: Inverse
    validation: Validation
    allow_expensive: bool = Field(
        False, description="true: build even a study larger than the cost guard's limits (estimated_costs)"
    )

    @model_validator(mode="after")
    def within_cost_limits(self):
        """Every study's size below its limit, unless ``allow_expensive: true`` (the estimate is reported)."""
        if not self.allow_expensive:
            for key, what, estimate, limit in estimated_costs(self):
                if estimate > limit:
                    raise ValueError(
                        f"{key}: an estimated {estimate:.3g} {what}, more than the limit {limit:.3g}; set "
                        "allow_expensive: true to build it anyway"
                    )
        return self

    @model_validator(mode="after")
    def sections_refer_to_each_other(self):
        """Claims readings, dense maps and notebooks name existing 1-DOF entries."""
        onedof = self.onedof
        check_refs([("claims.readings", r) for r in self.claims.readings], onedof.readings, "onedof.readings")
        for name, m in self.dense_map.maps.items():
            key = f"dense_map.maps.{name}"
            check_refs([(f"{key}.scene", m.scene)], onedof.scenes, "onedof.scenes")
            check_refs([(f"{key}.reading", m.reading)], onedof.readings, "onedof.readings")
            check_refs([(f"{key}.method", m.method)], onedof.methods, "onedof.methods")
            needs_switch(key, m.law, m.method, onedof.methods)
        for name, fig in self.inverse.figures.items():
            key = f"inverse.figures.{name}"
            check_refs([(f"{key}.scene", fig.scene)] if fig.scene else [], onedof.scenes, "onedof.scenes")
            check_refs([(f"{key}.sweep", fig.sweep)] if fig.sweep else [], onedof.sweeps, "onedof.sweeps")
        for name, nb in self.notebooks.items():
            key = f"notebooks.{name}"
            check_refs([(f"{key}.figures", f) for f in nb.figures or []], onedof.figures, "onedof.figures")
            figs = [(f"{key}.sweep_figures", f) for f in nb.sweep_figures or []]
            check_refs(figs, onedof.sweep_figures, "onedof.sweep_figures")
        return self


def json_schema() -> dict:
    """The JSON schema of ``PipelineConfig`` (what ``workflow/schemas/config.schema.json`` holds)."""
    schema = PipelineConfig.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema


def schema_text() -> str:
    return json.dumps(json_schema(), indent=1, sort_keys=True) + "\n"


if __name__ == "__main__":  # python -m stickslip.pipeline.config_models --write  (from the repository root)
    if sys.argv[1:] == ["--write"]:
        SCHEMA_PATH.write_text(schema_text())
    else:
        sys.stdout.write(schema_text())
