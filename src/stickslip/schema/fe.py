"""The ``fe`` section (``config/fe.yaml``): the beam on disc and the continuum strip."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, field_validator, model_validator

from ..catalogue import fe_paper_figure_numbers
from ..fe.params import Angle, BeamParams, ContactParams, DiscParams, SolverParams
from .base import Finite, Fraction, NonNegative, Positive, Section, check_refs, parameter_section

#: the paper's beam-on-disc figures, one PNG each (rule fe_figures)
FE_PAPER_FIGURES = tuple(fe_paper_figure_numbers())


Beam = parameter_section("Beam", BeamParams.model_fields)
Disc = parameter_section("Disc", DiscParams.model_fields)
Contact = parameter_section("Contact", ContactParams.model_fields)
FeSolver = parameter_section("FeSolver", SolverParams.model_fields)


#: The bin width [s] of a scene's binned series when its output gives none
DEFAULT_BIN_WIDTH = 1.0e-4


class FeOutput(Section):
    bin_width: Positive = Field(DEFAULT_BIN_WIDTH, description="s")
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
    output: FeOutput = FeOutput()


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
    units: str = "1"
    long_name: str | None = Field(None, description="the sweep coordinate's long name (default: coord)")
    #: an integer stays one (a sweep of beam.n_elements)
    values: Annotated[list[int | Finite], Field(min_length=2)]
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
    crosscheck: list[Annotated[list[Finite], Field(min_length=2, max_length=2)]] = []
    crosscheck_e_folds: Positive = Field(8.0, description="e-foldings of growth a cross-check transient runs")
    crosscheck_max_t_end: Positive = Field(0.05, description="longest cross-check transient [s]")
    #: disc speed label (as the scene names spell it) -> the scene whose disc speed sets the table slope
    speeds: dict[Annotated[str, Field(pattern=r"^[a-z0-9_]+$")], str] = {}

    @model_validator(mode="after")
    def crosscheck_slopes_bounded(self):
        for i, (_, slope) in enumerate(self.crosscheck):
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
    notes: dict[str, str] = {}
    claim_windows: dict[str, Positive] = Field(
        {}, description="scene -> t_end [s]: the continuum also runs these over a claim window (dt, dt/2)"
    )


class Increments(Section):
    base: str
    meshes: Annotated[list[Mesh], Field(min_length=1)]
    safety_factors: Annotated[list[Fraction], Field(min_length=1)]
    betas: Annotated[list[NonNegative], Field(min_length=1)]


class FePeer(Section):
    """The CalculiX peer of the continuum strip (rule fe_peer_calculix)."""

    mesh: Mesh = Field(
        [100, 1], description="nx, ny of the strip the continuum and CalculiX both solve (the paper's 100x1)"
    )
    tolerance: Fraction = Field(
        0.005, description="largest |relative difference| of any two of closed form, continuum, ccx"
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
    peer: FePeer = FePeer()
    paper_figures: dict[int, Annotated[list[str], Field(min_length=1)]] = Field(
        description="paper figure (21-36) -> the scenes it draws, the stated disc speed first"
    )

    @model_validator(mode="after")
    def bases_are_scenes(self):
        refs = [(f"fe.sweeps.{n}.base", sw.base) for n, sw in self.sweeps.items()]
        refs += [(f"fe.{k}.base", getattr(self, k).base) for k in ("convergence", "stability", "increments")]
        refs += [(f"fe.cross_scene.{n}", s) for n, triple in self.cross_scene.items() for s in triple[:2]]
        refs += [(f"fe.comparison.claim_windows.{n}", n) for n in self.comparison.claim_windows]
        refs += [(f"fe.paper_figures.{n}", s) for n, scenes in self.paper_figures.items() for s in scenes]
        check_refs(refs, self.scenes, "fe.scenes")
        return self

    @field_validator("paper_figures")
    @classmethod
    def every_beam_on_disc_figure_once(cls, figures):
        """One entry per figure the FE figure rule draws (Figs. 21-36), no other."""
        wanted = set(FE_PAPER_FIGURES)
        if set(figures) != wanted:
            missing, extra = sorted(wanted - set(figures)), sorted(set(figures) - wanted)
            raise ValueError(f"needs exactly Figs. 21-36 (missing {missing}, not beam-on-disc {extra})")
        return figures


class FeJob(Section):
    """What one FE job reads, its rule's params (``studies.fe_config.job_config``): its scenes resolved over
    the defaults and a reading, and the study sections it names. The whole ``fe`` section's references were
    checked at parse time; a job's part holds only what it runs."""

    scenes: dict[str, FeScene] = {}
    sweeps: dict[str, FeSweep] = {}
    convergence: Convergence | None = None
    stability: Stability | None = None
    increments: Increments | None = None
    comparison: Comparison | None = None
    cross_scene: dict[str, Annotated[list[str], Field(min_length=3, max_length=3)]] = {}
