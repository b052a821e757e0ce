"""The two checks of issue 13 as tables: switch solver vs an independent program (and a textbook closed
form), and the Fig. 17 round trip (the 1-DOF model driven by the table extracted from its own cycle)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.friction_curve import friction_table
from ..model.laws import FrictionLaw, LawModel, TabulatedLaw
from ..model.params import ParameterError
from ..schema import Peer, Tolerance
from ..solvers.base import STICK
from ..solvers.exact import sample_segments
from ..solvers.switch import SwitchSolver
from .cycle import QUANTITIES, coulomb_cycle, cycle_quantities, record_from_segments
from .peer import peer_events

#: Which tolerance (config ``validation.tolerances``) applies to each quantity, by its units.
TOLERANCE_CLASS = {q: ("time" if units == "s" else "position") for q, (units, _) in QUANTITIES.items()}


def compare_row(law: str, quantity: str, reference: str, value, ref_value, tol: Tolerance) -> dict:
    diff = abs(float(value) - float(ref_value))
    ok = bool(np.isfinite(diff) and diff <= tol.abs)
    return {
        "law": law,
        "quantity": quantity,
        "units": QUANTITIES[quantity][0],
        "reference": reference,
        "switch": float(value),
        "reference_value": float(ref_value),
        "abs_difference": diff,
        "tolerance": tol.abs,
        "status": "within" if ok else "exceeds",
        "tolerance_reason": tol.reason,
    }


def peer_comparison(
    name: str,
    model: LawModel,
    t_end: float,
    solver: SwitchSolver,
    peer: Peer,
    tolerances: dict[str, Tolerance],
    closed_form: bool = False,
) -> tuple[list[dict], dict]:
    """Rows comparing the switch solver's last cycle with CVODE's (and with the Coulomb closed form).

    Returns (rows, runs) where runs holds both programs' cycle quantities and work counters.
    """
    segments = solver.segments(model, t_end)
    mine = cycle_quantities(record_from_segments(segments))
    record, counters = peer_events(model, t_end, peer)
    theirs = cycle_quantities(record)
    if not all(np.isfinite(v) for v in mine.values()):
        raise ParameterError(f"validation.laws.{name}: no stick-slip cycle within t_end = {t_end} s")
    rows = [
        compare_row(name, q, "cvode", mine[q], theirs[q], tolerances[TOLERANCE_CLASS[q]]) for q in QUANTITIES
    ]
    if closed_form:
        p, law = model.params, model.law
        if p.damping != 0.0 or not hasattr(law, "mu_k"):
            raise ParameterError(f"validation.laws.{name}.closed_form: needs a Coulomb law and damping = 0")
        cf = coulomb_cycle(p.effective_mass, p.stiffness, p.normal_force, p.belt_velocity, law.mu_s, law.mu_k)
        rows += [
            compare_row(name, q, "closed_form", mine[q], cf[q], tolerances["closed_form"])
            for q in QUANTITIES
            if q in cf
        ]
    return rows, {"switch": mine, "cvode": theirs, "cvode_counters": counters, "segments": len(segments)}


def slip_friction_samples(t, x, v, vb, phase, law: FrictionLaw):
    """(|v_r|, mu) at every slip sample with v_r != 0 (as rule friction_table samples the cycle)."""
    vr = np.asarray(v) - np.asarray(vb)
    slip = (np.asarray(phase) != STICK) & np.isfinite(vr) & (vr != 0)
    speed = np.abs(vr[slip])
    return speed, np.asarray(law.mu(speed), dtype=float)


def table_from_segments(law: FrictionLaw, segments, t_eval, bins: int, belt_velocity) -> TabulatedLaw:
    """Fig. 17's projection for any law: mu at the slip samples of a run on ``t_eval``, binned."""
    x, v, phase = sample_segments(segments, t_eval)
    speed, mu = slip_friction_samples(t_eval, x, v, belt_velocity(t_eval), phase, law)
    table_v, table_mu = friction_table(speed, mu, law.static, bins)
    return TabulatedLaw(table_v, table_mu, source=f"projection of a {law.kind} cycle, {bins} bins")


@dataclass(frozen=True)
class RoundTrip:
    """The source cycle and the table-driven cycle on one time grid, and what separates them."""

    t: np.ndarray
    x_source: np.ndarray
    v_source: np.ndarray
    x_table: np.ndarray
    v_table: np.ndarray
    source: dict
    table: dict
    speed_grid: np.ndarray
    mu_law: np.ndarray
    mu_table: np.ndarray
    last_row_speed: float
    max_cycle_speed: float

    @property
    def differences(self) -> dict[str, float]:
        out = {f"d_{q}": self.table[q] - self.source[q] for q in QUANTITIES}
        out["max_abs_dx"] = float(np.max(np.abs(self.x_table - self.x_source)))
        out["max_abs_dv"] = float(np.max(np.abs(self.v_table - self.v_source)))
        inside = self.speed_grid <= self.last_row_speed
        out["table_error_inside"] = float(np.max(np.abs(self.mu_table - self.mu_law)[inside]))
        out["table_error_beyond"] = (
            float(np.max(np.abs(self.mu_table - self.mu_law)[~inside])) if (~inside).any() else 0.0
        )
        return out


def round_trip(source: LawModel, source_segments, table: TabulatedLaw, t_end, t_eval, solver) -> RoundTrip:
    """Run the table law from the source's initial state; compare with the source run (its ``segments``)."""
    seg_b = solver.segments(LawModel(source.params, table), t_end)
    xa, va, _ = sample_segments(source_segments, t_eval)
    xb, vb, _ = sample_segments(seg_b, t_eval)
    top = float(np.max(np.abs(va - source.belt_velocity(t_eval))))
    speeds = np.linspace(0.0, top, 2001)  # the range of relative speed the source cycle visits
    return RoundTrip(
        t=np.asarray(t_eval, dtype=float),
        x_source=xa,
        v_source=va,
        x_table=xb,
        v_table=vb,
        source=cycle_quantities(record_from_segments(source_segments)),
        table=cycle_quantities(record_from_segments(seg_b)),
        speed_grid=speeds,
        mu_law=np.asarray(source.law.mu(speeds), dtype=float),
        mu_table=np.asarray(table.mu(speeds), dtype=float),
        last_row_speed=float(table.speed[-1]),
        max_cycle_speed=top,
    )


def extended_table(table: TabulatedLaw, law: FrictionLaw, speed: float) -> TabulatedLaw:
    """The table with one more row at ``speed`` carrying the source law's value (a control case: it
    removes the one thing the projection cannot know, the law beyond the last bin's mean speed)."""
    if speed <= table.speed[-1]:
        raise ParameterError(f"extension_factor: the extra row at {speed} is inside the table")
    return TabulatedLaw(
        np.append(table.speed, speed),
        np.append(table.values, float(law.mu(speed))),
        static_mu=table.static_mu,
        source=f"{table.source} + 1 row at {speed:.6g} mm/s",
    )


def round_trip_cases(
    source: LawModel,
    table: TabulatedLaw,
    t_end: float,
    t_eval,
    solver: SwitchSolver,
    extension_factor: float,
    curved_law: FrictionLaw,
    bins: list[int],
    curved_solver: SwitchSolver | None = None,
) -> dict[str, RoundTrip]:
    """The Fig. 17 table against its source cycle; the same with the last row extended (control); and the
    projection of a curved law at several bin counts (binning error)."""
    source_segments = solver.segments(source, t_end)
    cases = {"fig17_table": round_trip(source, source_segments, table, t_end, t_eval, solver)}
    top = cases["fig17_table"].max_cycle_speed * extension_factor
    extended = extended_table(table, source.law, top)
    cases["fig17_table_extended"] = round_trip(source, source_segments, extended, t_end, t_eval, solver)
    # binning errors are >= 1e-6: a looser solver suffices there (PCHIP tables of a curved law have a jump
    # in the second derivative at every row, which costs a tight DOP853 many rejected steps)
    solver = curved_solver or solver
    curved = LawModel(source.params, curved_law)
    curved_segments = solver.segments(curved, t_end)
    for n in bins:
        projected = table_from_segments(curved_law, curved_segments, t_eval, n, curved.belt_velocity)
        cases[f"{curved_law.kind}_bins{n}"] = round_trip(
            curved, curved_segments, projected, t_end, t_eval, solver
        )
    return cases
