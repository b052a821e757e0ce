"""The forward model of the identification: the exact event-driven solver and the claims' metrics.

A parameter set is run (the compiled exact solver, ``solvers.exact_compiled``) exactly as the pipeline runs
a scene (same t_end, sample spacing, steady window) and
measured with the same definitions as ``analysis.metrics.limit_cycle_metrics`` (only the metrics a value
claim can name, without the spectrum, which no fitted claim uses; ``tests/inverse/test_inverse.py`` checks
they are equal). A run that fails, leaves finite numbers, or cannot produce a reported metric (no complete
stick interval, fewer than two peaks) is *infeasible*: its log-likelihood is -inf, never a zero residual.

Two hypotheses need laws the model layer does not have, built here from its parts:
``eq4_term``   the consistent sign with Eq. 4's sigma V_b term as printed (without the mu_s N factor);
``mu_k``       slip friction -mu_k N (sgn(v_r) - sigma v_r) with the stick limit mu_s N (mu_k < mu_s).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..analysis.metrics import count_peaks, displacement_peaks, frequency_from_peaks, intervals
from ..analysis.outcome import REST_FRACTION
from ..model.equations import BeltModel
from ..model.friction import AffineFriction, friction_law
from ..model.params import BeltParams, Fraction, ParameterError, Positive, checked_arguments, parameter_set
from ..solvers.base import STICK, Trajectory
from ..solvers.exact import ExactSwitchSolver
from ..solvers.exact_compiled import CompiledExactSolver
from .problem import Problem


@parameter_set(frozen=False)
class StaticKineticSolver(CompiledExactSolver):
    """The exact solver with a stick limit ``static_force`` [N] larger than the slip friction's |a|.

    Stick and the stick/slip decision use the static limit; slip uses the model's own (kinetic) law. Compiled
    (``_stick_a``); the Python hooks below are its reference (``exact_compiled.python_reference``).
    """

    static_force: Positive = field(kw_only=True)
    """The stick limit N mu_s [N]."""
    name: str = "exact_static_kinetic"

    def _stick_a(self, model: BeltModel) -> float:
        return -self.static_force

    def _static_model(self, model: BeltModel) -> BeltModel:
        return BeltModel(model.params, replace(model.friction, a=-self.static_force))

    def _stick(self, model, t0, x0, t_limit):
        return ExactSwitchSolver._stick(self._static_model(model), t0, x0, t_limit)

    def _contact_decision(self, model, t, x):
        return ExactSwitchSolver._contact_decision(self._static_model(model), t, x)


@checked_arguments(mu_k_ratio=Fraction)
def build_model(params: BeltParams, variant: str, eq4_term: bool = False, mu_k_ratio: float = 1.0):
    """(model, solver) of a parameter set under the family's variant and an optional hypothesis."""
    law = friction_law(params, variant)
    if eq4_term:
        if variant != "consistent":
            raise ParameterError("eq4_term: defined for the consistent variant only")
        law = replace(law, variant="consistent_eq4_term", kappa=-params.sigma)
    if mu_k_ratio < 1:
        mu_kn = mu_k_ratio * params.mu_s * params.normal_force
        law = AffineFriction(
            "consistent_mu_k",
            a=-mu_kn,
            b=mu_kn * params.sigma,
            kappa=-mu_kn * params.sigma if not eq4_term else -params.sigma,
            plateau_speed=law.plateau_speed,
        )
        return BeltModel(params, law), StaticKineticSolver(static_force=params.mu_s * params.normal_force)
    return BeltModel(params, law), CompiledExactSolver()


def observe(traj: Trajectory, transient: float, count_window: float, names) -> dict:
    """The named metrics of ``limit_cycle_metrics`` (same definitions), NaN where not measurable."""
    nan = float("nan")
    t, x, v = traj.t, traj.x, traj.v
    if not traj.ok or not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        return {n: nan for n in names}
    window = t >= transient
    tw, xw, vw = t[window], x[window], v[window]
    out = {}
    need = set(names)
    if need & {"stick_time", "slip_time", "stick_end_position"}:
        stick, slip = intervals(traj)
        t_end = t[-1]
        stick_c = stick[(stick[:, 0] >= transient) & (stick[:, 1] < t_end) & (stick[:, 0] > t[0])]
        slip_c = slip[(slip[:, 0] >= transient) & (slip[:, 1] < t_end) & (slip[:, 0] > t[0])]
        out["stick_time"] = float(np.mean(stick_c[:, 1] - stick_c[:, 0])) if len(stick_c) else nan
        out["slip_time"] = float(np.mean(slip_c[:, 1] - slip_c[:, 0])) if len(slip_c) else nan
        release = np.interp(stick_c[:, 1], t, x) if len(stick_c) else np.array([])
        out["stick_end_position"] = float(np.mean(release)) if len(release) else nan
    if need & {"max_speed", "max_speed_position"}:
        at = int(np.argmax(np.abs(vw)))
        out["max_speed"], out["max_speed_position"] = float(abs(vw[at])), float(xw[at])
    out["max_displacement"] = float(np.max(xw))
    out["amplitude_peak_to_peak"] = float(np.ptp(xw))
    out["amplitude_peak_to_zero"] = float(np.max(np.abs(xw)))
    if "stick_velocity" in need:
        sticking = traj.phase == STICK
        out["stick_velocity"] = float(np.mean(v[sticking])) if np.any(sticking) else nan
    if "frequency_peaks" in need:
        at_rest = np.ptp(xw) <= REST_FRACTION * max(np.ptp(x), 1e-300)
        out["frequency_peaks"] = nan if at_rest else float(frequency_from_peaks(tw, xw))
    if "peaks_in_count_window" in need:
        out["peaks_in_count_window"] = float(count_peaks(t, x, 0.0, count_window))
    if "periodic" in need:
        peaks = displacement_peaks(tw, xw)
        periodic = nan
        if len(peaks) >= 3:
            pv, spacing = xw[peaks], np.diff(tw[peaks])
            periodic = float(
                np.abs(pv[-1] - pv[-2]) <= 1e-3 * max(np.ptp(xw), 1e-12)
                and np.abs(spacing[-1] - spacing[-2]) <= 1e-3 * spacing[-1] + 2 * (tw[1] - tw[0])
            )
        out["periodic"] = periodic
    return {n: out[n] for n in names}


@dataclass
class Forward:
    """Measured numbers of a problem's observations for a free-parameter vector, with run counters.

    ``hypothesis`` may set ``eq4_term`` / ``mu_k_ratio`` (model laws), ``output_dt`` (sample spacing) or
    BeltParams fields (``units``, ``sigma``, ...) applied to every run on top of the free values.
    """

    problem: Problem
    hypothesis: dict = field(default_factory=dict)
    evaluations: int = 0
    infeasible: int = 0
    _cache: dict = field(default_factory=dict, repr=False)

    def run_metrics(self, free_values, run_index: int) -> dict:
        p = self.problem
        run = p.runs[run_index]
        hyp = dict(self.hypothesis)
        eq4, ratio = bool(hyp.pop("eq4_term", False)), float(hyp.pop("mu_k_ratio", 1.0))
        dt = float(hyp.pop("output_dt", p.run_settings["output_dt"]))  # a faster reading needs finer samples
        params = p.run_params(free_values, run, hyp)
        key = (tuple(sorted(params.as_dict().items())), eq4, ratio, dt)
        names = sorted({o.metric for o in p.observations if o.run == run_index})
        if key not in self._cache:
            model, solver = build_model(params, p.variant, eq4_term=eq4, mu_k_ratio=ratio)
            s = p.run_settings
            n = int(round(s["t_end"] / dt))
            with np.errstate(over="ignore", invalid="ignore"):  # runs growing without bound are data here
                traj = solver.solve(model, s["t_end"], np.linspace(0.0, n * dt, n + 1))
            self._cache[key] = observe(traj, s["transient"], s["count_window"], names)
            if len(self._cache) > 4096:
                self._cache.pop(next(iter(self._cache)))
        return self._cache[key]

    def measure(self, free_values) -> np.ndarray:
        """Measured value per observation (NaN where the run cannot produce it)."""
        self.evaluations += 1
        per_run = {}
        out = np.empty(len(self.problem.observations))
        for i, obs in enumerate(self.problem.observations):
            if obs.run not in per_run:
                per_run[obs.run] = self.run_metrics(free_values, obs.run)
            out[i] = per_run[obs.run].get(obs.metric, np.nan)
        return out

    def residuals(self, free_values) -> np.ndarray:
        """(measured - reported) / reading precision; NaN entries mark an infeasible parameter set."""
        obs = self.problem.observations
        value = np.array([o.value for o in obs])
        sd = np.array([o.sd for o in obs])
        r = (self.measure(free_values) - value) / sd
        if not np.all(np.isfinite(r)):
            self.infeasible += 1
        return r

    def log_likelihood(self, free_values) -> float:
        """Gaussian in the reading precision; -inf for an infeasible set (a failed run is not a zero)."""
        r = self.residuals(free_values)
        if not np.all(np.isfinite(r)):
            return -np.inf
        return -0.5 * float(r @ r)
