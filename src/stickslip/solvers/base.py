"""The common trajectory type and interface of every integration method."""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

#: Samples of a run's output when the caller gives no times (every method: one default, one place).
DEFAULT_SAMPLES = 2001


def default_t_eval(t_end: float, t_eval=None) -> np.ndarray:
    """``t_eval`` as an array, or DEFAULT_SAMPLES evenly spaced times over [0, t_end]."""
    return np.linspace(0.0, t_end, DEFAULT_SAMPLES) if t_eval is None else np.asarray(t_eval, dtype=float)


#: Phase codes stored per sample: slip with v < V_b, stick, slip with v > V_b.
SLIP_BACKWARD, STICK, SLIP_FORWARD = -1, 0, 1


class SolverError(RuntimeError):
    """A method could not proceed (step-size collapse, non-finite state, no progress)."""


@dataclass
class SolverStats:
    """Work counters of one solve; ``status`` is 'ok', 'failed' (numerical: nothing computed) or 'diverged'
    (the model's motion grows without bound: stickslip.analysis.divergence), with ``message`` saying why."""

    rhs_evaluations: int = 0
    steps: int = 0
    events: int = 0
    failures: int = 0
    cpu_time: float = 0.0
    status: str = "ok"
    message: str = ""


@dataclass
class Trajectory:
    """Samples of one solution on ``t`` plus the method's own switching record where it has one.

    ``segments`` (exact methods only) lists (t_start, t_end, phase) of every stick/slip segment, so
    interval lengths are known to machine precision rather than to the sample spacing.
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    phase: np.ndarray
    belt_velocity: np.ndarray
    stats: SolverStats
    method: str
    settings: dict = field(default_factory=dict)
    segments: np.ndarray | None = None

    @classmethod
    def failed(
        cls, t, belt_velocity, stats: SolverStats, method: str, settings: dict | None = None, segments=None
    ):
        """The one way to record a failed solve: NaN samples on ``t`` (never plotted as a result), phase 0,
        the belt velocity for reference and the counters in ``stats`` (status 'failed' with its message).
        ``segments``: an empty table for a method that records segments, so its datasets keep their shape."""
        t = np.asarray(t, dtype=float)
        nan = np.full(t.shape, np.nan)
        return cls(
            t=t,
            x=nan,
            v=nan.copy(),
            phase=np.zeros(t.shape, dtype=np.int8),
            belt_velocity=np.asarray(belt_velocity, dtype=float),
            stats=stats,
            method=method,
            settings=dict(settings or {}),
            segments=segments,
        )

    @property
    def ok(self) -> bool:
        return self.stats.status == "ok"

    @property
    def relative_velocity(self) -> np.ndarray:
        return self.v - self.belt_velocity


def sample_times(t_end: float, dt: float) -> np.ndarray:
    """Uniform output samples dt apart from 0 that never pass t_end. (n dt can exceed t_end by a rounding
    error, e.g. when t_end and dt carry independent last-digit perturbations; a sample past the last
    solution segment would be NaN.)"""
    n = int(round(t_end / dt))
    return np.linspace(0.0, min(n * dt, t_end), n + 1)


def classify_phase(v, vb, tolerance: float) -> np.ndarray:
    """Phase per sample of a smooth-method trajectory: stick where |v - V_b| <= tolerance."""
    vr = np.asarray(v) - np.asarray(vb)
    phase = np.sign(vr).astype(np.int8)
    phase[np.abs(vr) <= tolerance] = STICK
    return phase


def reading_model(model, solver: str):
    """The model a solver of the paper's readings (exact, sign-RK, smoothed, Karnopp, Moreau) integrates.

    Those solvers need the readings' affine friction (``model.friction``). A ``LawModel`` of an affine law is
    that law's ``consistent`` reading and is converted; any other friction law (Stribeck, Coulomb, rational,
    tabulated) is solved by the switch solver only, and the error says so by name instead of failing later
    on a missing attribute."""
    law = getattr(model, "law", None)
    if law is None or hasattr(model, "friction"):
        return model
    from ..model.equations import BeltModel
    from ..model.laws import AffineLaw, LawModel
    from ..model.params import ParameterError

    if isinstance(model, LawModel) and isinstance(law, AffineLaw):
        params = model.params.with_(mu_s=law.mu_s, sigma=law.sigma, plateau_speed=law.plateau_speed)
        return BeltModel.build(params, "consistent")
    raise ParameterError(
        f"solver: {solver!r} integrates the paper's affine friction readings only; a {law.kind!r} friction "
        "law needs the 'switch' solver (make_solver('switch'), or a method whose solver is 'switch')"
    )


def checked_t_end(t_end, method: str) -> float:
    """``t_end`` as a float; anything but a finite number > 0 is bad input, raised, never a failed run."""
    try:
        value = float(t_end)
    except (TypeError, ValueError):
        value = float("nan")
    if not (np.isfinite(value) and value > 0):
        raise SolverError(f"{method} solver: t_end must be a finite number > 0, got {t_end!r}")
    return value


def record_failure(stats: SolverStats, message: str) -> None:
    stats.status, stats.message, stats.failures = "failed", message, 1


@dataclass
class Samples:
    """A method's solution on the output times, as its ``_sample`` hook returns it."""

    x: np.ndarray
    v: np.ndarray
    phase: np.ndarray
    segments: np.ndarray | None = None
    failure: str = ""
    """Non-empty: the run failed although it has samples, which are kept as they are (e.g. non-finite)."""


class OneDofSolver:
    """The stepping contract of every 1-DOF method, split as scipy's ``OdeSolver`` splits ``step`` from
    ``_step_impl``: this class owns ``solve()`` (model conversion, t_end check, output times, counters and
    CPU time, a ``SolverError`` becoming ``Trajectory.failed``); a method supplies only

    * ``_integrate(model, t_end, stats) -> raw``: the integration itself (timed; counters go to ``stats``;
      raises ``SolverError`` when it cannot proceed), and
    * ``_sample(raw, t_eval, belt_velocity) -> Samples``: that solution on the output times (not timed),

    plus ``SETTING_NAMES`` and, where they differ from the defaults, ``label``, ``_integrated`` and
    ``_solve_settings``. A method is a ``model.params.parameter_set(frozen=False)`` dataclass with a ``name``
    field: each setting's type and bound are its field's annotation, checked when the method is built (a
    bad value in the config fails when the pipeline starts, naming the setting, not inside a job).
    """

    name: str
    #: The fields a trajectory records as the method's settings, in this order.
    SETTING_NAMES: tuple[str, ...] = ()
    #: A method that records stick/slip segments stores an empty table when it fails (same dataset layout).
    records_segments = False

    # -- hooks ----------------------------------------------------------------------------------------
    @property
    def settings(self) -> dict:
        return {name: getattr(self, name) for name in self.SETTING_NAMES}

    @property
    def label(self) -> str:
        """The method name a trajectory is stored under."""
        return self.name

    def _integrated(self, model):
        """The model this method integrates: the paper's affine readings unless a method says otherwise."""
        return reading_model(model, self.name)

    def _solve_settings(self, model) -> dict:
        return self.settings

    def _integrate(self, model, t_end: float, stats: SolverStats):
        raise NotImplementedError

    def _sample(self, raw, t_eval: np.ndarray, belt_velocity: np.ndarray) -> Samples:
        raise NotImplementedError

    # -- owned here -----------------------------------------------------------------------------------
    def solve(self, model, t_end: float, t_eval=None) -> Trajectory:
        """Samples on ``t_eval`` (default DEFAULT_SAMPLES points over [0, t_end]); bad input raises, a run
        that cannot proceed is a failed trajectory with its counters."""
        model = self._integrated(model)
        t_end = checked_t_end(t_end, self.name)
        stats = SolverStats()
        start = time.process_time()  # process CPU time: insensitive to other load on the machine
        try:
            raw = self._integrate(model, t_end, stats)
        except SolverError as exc:
            record_failure(stats, str(exc))
        stats.cpu_time = time.process_time() - start
        t_eval = default_t_eval(t_end, t_eval)
        belt = model.belt_velocity(t_eval)
        settings = self._solve_settings(model)
        if stats.status == "failed":
            no_segments = np.empty((0, 3)) if self.records_segments else None
            return Trajectory.failed(t_eval, belt, stats, self.label, settings, segments=no_segments)
        samples = self._sample(raw, t_eval, belt)
        if samples.failure:
            record_failure(stats, samples.failure)
        return Trajectory(
            t=t_eval,
            x=samples.x,
            v=samples.v,
            phase=samples.phase,
            belt_velocity=belt,
            stats=stats,
            method=self.label,
            settings=settings,
            segments=samples.segments,
        )
