"""The independent check (CVODE hybrid model), the Coulomb closed form, cycle quantities, the round trip."""

import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from pydantic import ValidationError

from stickslip.model import PAPER_BASELINE
from stickslip.model.laws import AffineLaw, CoulombLaw, LawModel, RationalLaw, StribeckLaw
from stickslip.model.params import ParameterError
from stickslip.schema import Validation, ValidationLaw
from stickslip.solvers.switch import SwitchSolver
from stickslip.validation import setup
from stickslip.validation.compare import (
    extended_table,
    peer_comparison,
    round_trip,
    table_from_segments,
)
from stickslip.validation.cycle import EventRecord, coulomb_cycle, cycle_quantities
from stickslip.validation.peer import peer_events

CONFIG = yaml.safe_load((Path(__file__).parents[2] / "config" / "validation.yaml").read_text())["validation"]
VALIDATION = Validation.model_validate(CONFIG)
BASE = PAPER_BASELINE.with_(sigma=0.5)


@pytest.mark.parametrize(
    "name, model",
    [
        ("affine", LawModel(BASE, AffineLaw(0.5, 0.5))),
        ("stribeck", LawModel(BASE, StribeckLaw(0.5, 0.3, 0.2))),
        ("rational", LawModel(BASE, RationalLaw(0.5, 1.0))),
        ("coulomb", LawModel(BASE.with_(damping=0.0), CoulombLaw(0.5, 0.3))),
    ],
)
def test_switch_solver_agrees_with_cvode_within_the_configured_tolerance(name, model):
    rows, runs = peer_comparison(
        name,
        model,
        25.0,
        setup.switch_solver(VALIDATION.solver, "validation.solver"),
        VALIDATION.peer,
        dict(VALIDATION.tolerances),
    )
    assert len(rows) == 7 and runs["cvode_counters"]["rhs_evaluations"] > 100
    bad = [(r["quantity"], r["abs_difference"], r["tolerance"]) for r in rows if r["status"] != "within"]
    assert not bad


def test_cvode_alone_reproduces_the_textbook_coulomb_cycle():
    """The peer program against the closed form, with the switch solver out of the loop."""
    p = BASE.with_(damping=0.0)
    record, _ = peer_events(LawModel(p, CoulombLaw(0.5, 0.3)), 25.0, VALIDATION.peer)
    q = cycle_quantities(record)
    cf = coulomb_cycle(p.mass, p.stiffness, p.normal_force, p.belt_velocity, 0.5, 0.3)
    for key in ("period", "stick_duration", "release_position", "onset_position", "x_max", "x_min"):
        assert q[key] == pytest.approx(cf[key], abs=1e-7), key


def test_coulomb_closed_form_by_hand():
    """w = sqrt(5), x_k = 0.6, Delta = 0.4, V_b = 0.5: a cycle computed from the formulas' pieces."""
    cf = coulomb_cycle(1.0, 5.0, 10.0, 0.5, 0.5, 0.3)
    w = math.sqrt(5.0)
    amplitude = math.sqrt(0.4**2 + (0.5 / w) ** 2)
    assert cf["stick_duration"] == pytest.approx(0.8 / 0.5)
    assert cf["period"] == pytest.approx(1.6 + (math.pi + 2 * math.atan(0.5 / (w * 0.4))) / w)
    assert (cf["x_max"], cf["x_min"]) == pytest.approx((0.6 + amplitude, 0.6 - amplitude))
    # the slip ends where the mirror image of the release sits: energy about x_k is conserved in slip
    assert 0.5 * 5.0 * (cf["onset_position"] - 0.6) ** 2 == pytest.approx(
        0.5 * 5.0 * (cf["release_position"] - 0.6) ** 2
    )
    with pytest.raises(ParameterError, match="^mu_k"):
        coulomb_cycle(1.0, 5.0, 10.0, 0.5, 0.3, 0.3)


def test_cycle_quantities_of_a_hand_made_record():
    record = EventRecord(
        onsets=np.array([[1.0, 0.2], [4.0, 0.25]]),
        releases=np.array([[2.5, 0.9], [5.5, 0.9]]),
        extrema=np.array([[3.0, 1.1], [3.6, 0.1], [4.5, 2.0]]),
    )
    q = cycle_quantities(record)
    assert (q["period"], q["stick_onset"], q["stick_duration"]) == (3.0, 4.0, 1.5)
    assert (q["x_max"], q["x_min"], q["onset_position"], q["release_position"]) == (1.1, 0.1, 0.25, 0.9)
    assert all(math.isnan(v) for v in cycle_quantities(EventRecord(*(np.zeros((0, 2)),) * 3)).values())


def test_round_trip_of_a_linear_law_is_exact_once_the_table_covers_the_cycle():
    """Bin means of a straight line lie on it: the table is the law up to its last row. Held beyond that row,
    it changes the cycle; extended by one row at the top speed, the cycle comes back to solver precision."""
    solver = SwitchSolver()
    source = LawModel(BASE, AffineLaw(0.5, 0.5))
    t = np.linspace(0.0, 25.0, 2501)
    segments = solver.segments(source, 25.0)
    table = table_from_segments(source.law, segments, t, 24, source.belt_velocity)
    held = round_trip(source, segments, table, 25.0, t, solver)
    assert held.differences["table_error_inside"] < 1e-12
    assert abs(held.differences["d_period"]) > 1e-4
    full = round_trip(
        source, segments, extended_table(table, source.law, 1.05 * held.max_cycle_speed), 25.0, t, solver
    )
    assert abs(full.differences["d_period"]) < 1e-9 and full.differences["max_abs_dx"] < 1e-8


def test_binning_error_of_a_curved_law_is_second_order():
    solver = SwitchSolver(rtol=1e-9, atol=1e-10)
    source = LawModel(BASE, StribeckLaw(0.5, 0.3, 0.2))
    t = np.linspace(0.0, 25.0, 2501)
    segments = solver.segments(source, 25.0)
    errors = []
    for bins in (12, 24, 48):
        table = table_from_segments(source.law, segments, t, bins, source.belt_velocity)
        errors.append(abs(round_trip(source, segments, table, 25.0, t, solver).differences["d_period"]))
    assert errors[0] / errors[1] > 3 and errors[1] / errors[2] > 3


def test_validation_config_errors_name_the_key():
    tolerances = CONFIG["tolerances"]
    for bad, key in [
        ({"abs": 1e-7}, r"tolerances\.time\.reason"),
        ({"abs": 1e-7, "reason": "  "}, r"tolerances\.time\.reason"),
        ({"abs": float("nan"), "reason": "x"}, r"tolerances\.time\.abs"),
    ]:
        with pytest.raises(ValidationError, match=key):
            Validation.model_validate({**CONFIG, "tolerances": {**tolerances, "time": bad}})
    stribeck = {"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.9, "v_s": 1}
    bad_law = VALIDATION.model_copy(update={"laws": {"x": ValidationLaw.model_validate({"law": stribeck})}})
    with pytest.raises(ParameterError, match=r"^validation\.laws\.x\.law\.mu_k"):
        setup.check(bad_law, producible=[])
    table = ValidationLaw.model_validate({"law": {"kind": "tabulated", "path": "nowhere.csv"}})
    with pytest.raises(ParameterError, match=r"^validation\.laws\.t\.law\.path"):
        setup.check(VALIDATION.model_copy(update={"laws": {"t": table}}), producible=[])
    setup.check(VALIDATION, producible=["results/onedof/friction_mu_vr.csv"])  # the shipped config
