"""An identification problem: runs of the forward model, the reported numbers they must reproduce, the free
parameters with their bounds, and the directions of parameter space the numbers can identify at all.

The reported numbers and their tolerances come from the claims table by claim id; the stated
parameters from the pipeline config (onedof.defaults and the figure's scene or sweep). Nothing is copied.

Identifiability. In the units-as-given reading the equation of motion divided by M is

    x'' + (C/M) x' + (K/M) x = -(mu_s N / M) (sgn(v_r) - sigma v_r'),

so a run depends on M, K, C, mu_s, N only through K/M, C/M and mu_s N/M (plus sigma and the plateau speed).
In log10 coordinates these are linear maps (rows of ``COMBINATIONS``); a problem whose runs fix some
parameters (a sweep, the changed parameter of a figure) identifies the row space of the stacked maps, and
the orthogonal complement is exactly flat in the likelihood. The sampler works in the identifiable
coordinates; a raw parameter set is reported as the one *closest to the stated set* (in log10 distance) among
all sets giving the same motion: stated + B w, with B an orthonormal basis of the identifiable directions.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import get_args

import numpy as np

from .. import catalogue
from ..analysis.metrics import PAPER_COUNT_WINDOW
from ..claims.rows import Claim
from ..model.params import BeltParams, ParameterError
from ..schema import InverseJob, InverseOnedof, InverseParameter, given

#: Free parameters the study may vary, in a fixed order (BeltParams field names): the config's own type.
PARAMS = get_args(InverseParameter)
SYMBOLS = dict(zip(PARAMS, ("sigma", "C", "mu_s", "N", "K", "M", "v_p")))
UNITS = dict(zip(PARAMS, ("s mm-1", "N s mm-1", "1", "N", "N mm-1", "kg", "mm s-1")))

#: log10 of the combinations a run depends on, as rows over PARAMS.
COMBINATIONS = {
    "K/M": {"stiffness": 1, "mass": -1},
    "C/M": {"damping": 1, "mass": -1},
    "mu_s N/M": {"mu_s": 1, "normal_force": 1, "mass": -1},
    "sigma": {"sigma": 1},
    "v_p": {"plateau_speed": 1},
}
COMBINATION_UNITS = {"K/M": "s-2", "C/M": "s-1", "mu_s N/M": "mm s-2", "sigma": "s mm-1", "v_p": "mm s-1"}

#: Metrics a value claim may name (the subset of ``limit_cycle_metrics`` the forward model measures).
METRICS = (
    "max_displacement",
    "stick_time",
    "slip_time",
    "frequency_peaks",
    "peaks_in_count_window",
    "stick_velocity",
    "max_speed",
    "max_speed_position",
    "stick_end_position",
    "amplitude_peak_to_peak",
    "amplitude_peak_to_zero",
    "periodic",
)


@dataclass(frozen=True)
class Observation:
    """One reported number: the claim row's value and its reading precision (one standard deviation)."""

    claim: str
    run: int
    metric: str
    value: float
    sd: float
    unit: str
    figure: str


@dataclass(frozen=True)
class RunDef:
    """One run of the forward model: parameters this run fixes on top of the free ones."""

    name: str
    overrides: dict = field(default_factory=dict)


@dataclass(frozen=True)
class Problem:
    name: str
    title: str
    family: str
    variant: str
    stated: dict
    """Stated value of every BeltParams field (the base scene's caption values)."""
    free: tuple
    bounds: dict
    runs: tuple
    observations: tuple
    run_settings: dict
    nonnegative_plateau: bool = True

    @property
    def stated_free(self) -> np.ndarray:
        return np.array([self.stated[p] for p in self.free], dtype=float)

    @property
    def log_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        lo = np.log10([self.bounds[p][0] for p in self.free])
        hi = np.log10([self.bounds[p][1] for p in self.free])
        return lo, hi

    @property
    def plateau_pair(self) -> tuple[int, int] | None:
        """Indices in ``free`` of sigma and v_p where the plateau constraint sigma v_p <= 1 applies."""
        if self.nonnegative_plateau and "plateau_speed" in self.free:
            return self.free.index("sigma"), self.free.index("plateau_speed")
        return None

    def values(self, free_values) -> dict:
        """Free parameter values as a mapping."""
        return dict(zip(self.free, (float(v) for v in free_values)))

    def run_params(self, free_values, run: RunDef, extra: dict | None = None) -> BeltParams:
        """Parameters of one run: stated, then the free values, then what the run fixes (its overrides)."""
        mapping = {**self.stated, **self.values(free_values), **run.overrides, **(extra or {})}
        return BeltParams(**mapping)

    def in_bounds(self, free_values) -> bool:
        v = np.asarray(free_values, dtype=float)
        lo, hi = (10.0**b for b in self.log_bounds)
        if not (np.all(np.isfinite(v)) and np.all(v >= lo * (1 - 1e-12)) and np.all(v <= hi * (1 + 1e-12))):
            return False
        if self.nonnegative_plateau and "plateau_speed" in self.free:
            vals = self.values(v)
            if vals.get("sigma", self.stated["sigma"]) * vals["plateau_speed"] > 1.0:
                return False
        return True

    # -- identifiable directions ------------------------------------------------------------------------
    def combination_matrix(self) -> np.ndarray:
        """Stacked log-combination rows over the free parameters, one block per run (fixed columns zeroed)."""
        rows = []
        for run in self.runs:
            for combo in COMBINATIONS.values():
                row = [0.0 if p in run.overrides else float(combo.get(p, 0)) for p in self.free]
                if any(row):
                    rows.append(row)
        return np.array(rows, dtype=float).reshape(-1, len(self.free))

    def identifiable_basis(self) -> np.ndarray:
        """Orthonormal basis (columns) of the free log10 directions that change at least one run."""
        a = self.combination_matrix()
        _, s, vt = np.linalg.svd(a, full_matrices=False)
        rank = int(np.sum(s > 1e-10 * max(s.max(), 1.0)))
        basis = vt[:rank].T
        # a deterministic sign: the largest entry of each column positive
        signs = np.sign(basis[np.argmax(np.abs(basis), axis=0), np.arange(rank)])
        return basis * signs

    def null_basis(self) -> np.ndarray:
        """Orthonormal basis (columns) of the free log10 directions that change no run: the same motion."""
        basis = self.identifiable_basis()
        n, k = basis.shape
        return np.linalg.svd(basis.T, full_matrices=True)[2][k:].T if k < n else np.zeros((n, 0))

    def from_coordinates(self, w) -> np.ndarray:
        """Free parameter values of identifiable coordinates w: the set closest to the stated one."""
        basis = self.identifiable_basis()
        return 10.0 ** (np.log10(self.stated_free) + basis @ np.asarray(w, dtype=float))

    def to_coordinates(self, free_values) -> np.ndarray:
        basis = self.identifiable_basis()
        return basis.T @ (np.log10(np.asarray(free_values, dtype=float)) - np.log10(self.stated_free))

    def closest_equivalent(self, free_values) -> np.ndarray:
        """The set giving the same motion as ``free_values`` that is closest to the stated set."""
        return self.from_coordinates(self.to_coordinates(free_values))

    def combinations(self, free_values) -> dict:
        """K/M, C/M, mu_s N/M, sigma (and v_p, where free) of a parameter set in the first run."""
        p = self.run_params(free_values, self.runs[0]).as_dict()
        return {
            name: float(np.prod([p[k] ** e for k, e in combo.items()]))
            for name, combo in COMBINATIONS.items()
            if name != "v_p" or "plateau_speed" in self.free
        }


# -- building problems from the config and the claims table ----------------------------------------------


def load_claim_rows(paths) -> dict[str, Claim]:
    """Claim id -> row, read (and checked) by the claims table's own loader."""
    from ..claims.load import load_claims

    return by_id(load_claims(paths))


def by_id(claims) -> dict[str, Claim]:
    """Claim id -> row of rows already read (ids are unique: the loader checks)."""
    return {row.id: row for row in claims}


def _tolerance_sd(row: Claim) -> float:
    """The reading precision of a value row as a standard deviation: its relative band if it has one (a
    value row always has a tolerance with rel or abs: stickslip.claims.rows)."""
    tol = row.tolerance
    where = f"claim {row.id}.tolerance"
    sd = tol.rel * abs(row.value) if tol.rel is not None else tol.abs
    if not (math.isfinite(sd) and sd > 0):  # rel or abs 0 is a valid band, but no spread to fit with
        raise ParameterError(f"{where}: must give a positive spread, got {sd!r}")
    return sd


#: a claim names a per-reading dataset with this placeholder for the reading
ANY_READING = "{reading}"


def runs_by_dataset(scenes: Iterable[str], sweeps: Iterable[str]) -> dict[str, tuple[str, str]]:
    """Dataset path -> ("scene" | "sweep", its name), for the named 1-DOF scenes and sweeps: the paths a
    value claim names (the catalogue's exact-solver ``onedof_dataset`` and ``sweep_dataset``, the reading
    left as the claims' ``{reading}`` placeholder)."""
    out = {catalogue.onedof_dataset(name, ANY_READING, "exact"): ("scene", name) for name in scenes}
    out.update({catalogue.sweep_dataset(name, ANY_READING): ("sweep", name) for name in sweeps})
    return out


def _value_tag(value: float) -> str:
    return f"{value:g}".replace(".", "p")  # as workflow/scripts/onedof_sweeps.py names the variables


def claim_run(row: Claim, onedof: InverseOnedof) -> tuple[str, str, dict]:
    """(run name, metric, overrides relative to the defaults) of a value claim: its dataset looked up among
    the datasets the config's scenes and sweeps produce (``runs_by_dataset``)."""
    where = f"claim {row.id}"
    if row.kind != "value":
        raise ParameterError(f"{where}.kind: only value claims are reported numbers (got {row.kind!r})")
    if row.comparable is False:
        raise ParameterError(f"{where}.comparable: false (the paper contradicts itself there); not fitted")
    path, variable = row.dataset, row.variable
    kind, name = runs_by_dataset(onedof.scenes, onedof.sweeps).get(path, (None, None))
    if kind == "scene":
        if variable not in METRICS:
            raise ParameterError(f"{where}.variable: {variable!r} is not one of {METRICS}")
        return name, variable, given(onedof.scenes[name].params)
    if kind == "sweep":
        sweep = onedof.sweeps[name]
        metric, _, tag = variable.rpartition("_at_")
        try:  # the paper's value is in the variable's name (0p9 = 0.9), whatever values a config sweeps
            value = float(tag.replace("p", "."))
        except ValueError:
            value = None
        if metric not in METRICS or value is None or _value_tag(value) != tag:
            raise ParameterError(f"{where}.variable: {variable!r} is not <metric>_at_<sweep value>")
        overrides = {sweep.parameter: value, **{k: f * value for k, f in (sweep.linked or {}).items()}}
        base = given(onedof.scenes[sweep.scene or onedof.baseline.scene].params)
        return f"{name}:{sweep.parameter}={value:g}", metric, {**base, **overrides}
    scene, sweep = runs_by_dataset(["<scene>"], ["<sweep>"])
    raise ParameterError(
        f"{where}.dataset: {path!r} is neither the exact-solver dataset of a scene in onedof.scenes "
        f"({scene}) nor a sweep in onedof.sweeps ({sweep})"
    )


def build_problem(job: InverseJob, claims: dict[str, Claim], name: str, family: str) -> Problem:
    """The identification problem of one figure (or ``joint``) for one model family."""
    inv, onedof = job.inverse, job.onedof
    fam = inv.families[family]
    figures = inv.joint if name == "joint" else [name]
    stated = {**given(onedof.defaults.params), **(inv.stated or {})}
    if "plateau_speed" not in fam.free:
        stated["plateau_speed"] = math.inf
    runs: list[RunDef] = []
    observations = []
    for fig in figures:
        figure = inv.figures[fig]
        one_scene = name != "joint" and figure.scene is not None
        for cid in figure.claims:
            if cid not in claims:
                raise ParameterError(f"inverse.figures.{fig}.claims: {cid!r} is not a claim id")
            row = claims[cid]
            run_name, metric, overrides = claim_run(row, onedof)
            if one_scene:
                overrides = {}  # one scene: every parameter free, its caption values the stated ones
            names = [r.name for r in runs]
            if run_name not in names:
                runs.append(RunDef(run_name, overrides))
                names.append(run_name)
            observations.append(
                Observation(
                    claim=cid,
                    run=names.index(run_name),
                    metric=metric,
                    value=row.value,
                    sd=_tolerance_sd(row),
                    unit=row.unit,  # a value row always has one (stickslip.claims.rows)
                    figure=fig,
                )
            )
        if one_scene:
            stated.update(given(onedof.scenes[figure.scene].params))
    fixed = [set(run.overrides) & set(fam.free) for run in runs]  # a sweep's parameter: every run sets it
    fixed_everywhere = set.intersection(*fixed) if fixed else set()
    free = tuple(p for p in PARAMS if p in fam.free and p not in fixed_everywhere)
    defaults = onedof.defaults
    return Problem(
        name=name,
        title="Sections 3-5 jointly" if name == "joint" else inv.figures[name].title,
        family=family,
        variant=fam.variant,
        stated=stated,
        free=free,
        bounds={p: (inv.bounds[p].min, inv.bounds[p].max) for p in PARAMS},
        runs=tuple(runs),
        observations=tuple(observations),
        run_settings={
            "t_end": defaults.t_end,
            "output_dt": defaults.output_dt,
            "transient": defaults.transient or 0.0,
            "count_window": defaults.count_window or PAPER_COUNT_WINDOW,
        },
        nonnegative_plateau="nonnegative_plateau_friction" in (inv.constraints or {}),
    )
