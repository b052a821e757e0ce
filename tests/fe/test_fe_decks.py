"""Decks that run (issue 41): ccx runs every scene's CalculiX variant to completion, and the ABAQUS/Explicit
scene decks use only documented keyword parameter values and request the contact and energy history the
claims read.

ccx runs a reduced-time variant of each scene's ccx deck: the same generator (``ccx_scene_deck``) and mesh
as the deck rule ``fe_decks`` writes, 5 us instead of ``CCX_T_END`` (0.5 ms take ~30-60 s of CPU each; 5 us
take ~0.7 s: the contact closes and carries load, friction acts within mu N, every keyword is read and
executed; 20 us took 3x the CPU for the same checks)."""

import numpy as np
import pytest
import yaml

from stickslip.catalogue import FE_CCX_SUFFIX
from stickslip.fe.abaqus_deck import (
    CONTACT_NODE_VARIABLES,
    CONTACT_TOTALS,
    ENERGY_VARIABLES,
    _params,
    read_deck,
    scene_deck,
)
from stickslip.fe.ccx_deck import CCX_MAX_INCREMENT, ccx_scene_deck, contact_frame
from stickslip.fe.params import BeamParams, ContactParams, FrictionTable
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import scene_mapping
from stickslip.validation.calculix import dat_time_series, run_ccx

from project_run import ROOT, require_ccx

FE = Fe.model_validate(yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"])
SCENES = list(FE.scenes)
NX, NY = FE.comparison.mesh
TEST_T_END = 5.0e-6  # s: the reduced window ccx runs here (see the module docstring)

#: Keyword -> {parameter: allowed values (None: any value, e.g. a name or a number)} of the ABAQUS/Explicit
#: scene decks, from the Abaqus Keywords Reference (v6.x/2016 keyword pages, e.g.
#: http://130.149.89.49:2080/v2016/books/key/ch03abk68.html (*CONTACT PAIR: "MECHANICAL CONSTRAINT" =
#: KINEMATIC (default) or PENALTY, Abaqus/Explicit), ch06abk40.html (*FRICTION), and the pages of the
#: other keywords below; the *FRICTION data line is "mu, slip rate, contact pressure, temperature").
#: A parameter without a value (a flag) is listed with the value "".
DOCUMENTED = {
    "*HEADING": {},
    "*NODE": {"NSET": None},
    "*ELEMENT": {"TYPE": {"CPS4R"}, "ELSET": None},
    "*NSET": {"NSET": None},
    "*ELSET": {"ELSET": None},
    "*SURFACE": {"TYPE": {"ELEMENT", "SEGMENTS"}, "NAME": None},
    "*RIGID BODY": {"REF NODE": None, "ANALYTICAL SURFACE": None},
    "*MATERIAL": {"NAME": None},
    "*ELASTIC": {},
    "*DENSITY": {},
    "*DAMPING": {"BETA": None},
    "*SOLID SECTION": {"ELSET": None, "MATERIAL": None, "CONTROLS": None},
    "*SECTION CONTROLS": {"NAME": None, "HOURGLASS": {"ENHANCED"}},
    "*SURFACE INTERACTION": {"NAME": None},
    "*FRICTION": {},
    "*SURFACE BEHAVIOR": {"PRESSURE-OVERCLOSURE": {"LINEAR"}},
    "*BOUNDARY": {"TYPE": {"VELOCITY"}},
    "*STEP": {"NLGEOM": {"YES"}},
    "*DYNAMIC": {"EXPLICIT": {""}},
    "*BULK VISCOSITY": {},
    "*DLOAD": {},
    "*CONTACT PAIR": {"INTERACTION": None, "MECHANICAL CONSTRAINT": {"KINEMATIC", "PENALTY"}},
    "*OUTPUT": {"HISTORY": {""}, "FIELD": {""}, "TIME INTERVAL": None},
    "*NODE OUTPUT": {"NSET": None},
    "*CONTACT OUTPUT": {"SLAVE": None, "MASTER": None, "NSET": None},
    "*ENERGY OUTPUT": {},
    "*END STEP": {},
}


@pytest.mark.parametrize("scene", SCENES)
def test_ccx_runs_the_ccx_variant_of_every_scene_to_completion(scene, tmp_path):
    require_ccx()
    mapping = scene_mapping(FE, scene)
    deck = ccx_scene_deck(scene, mapping, NX, NY, t_end=TEST_T_END, dt=CCX_MAX_INCREMENT)
    dat = run_ccx(deck, scene + FE_CCX_SUFFIX, workdir=tmp_path, timeout=120.0)  # raises on any *ERROR
    series = dat_time_series(dat)
    t, tip = series[("displacements", "TIPLOW")]
    _, rf = series[("total force", "BLOCKN")]
    assert t[-1] == pytest.approx(TEST_T_END, rel=1e-6)  # ran to the end of the step
    assert np.all(np.isfinite(tip)) and np.all(np.isfinite(rf))
    beam = BeamParams.from_mapping(mapping["beam"])
    contact = ContactParams.from_mapping(mapping["contact"])
    _, n, tan = contact_frame(beam, contact, mapping["disc"].get("direction", "clockwise"))
    normal = rf[:, :2] @ n
    assert normal[-1] > 0  # the strip presses on the block: the contact carries load
    assert abs(rf[-1, :2] @ tan) <= 0.4 * normal[-1] * (1 + 1e-6)  # friction within mu N
    for what in ("total kinetic energy", "total internal energy"):
        assert series[(what, "STRIP")][1][-1, 0] > 0


@pytest.mark.parametrize("scene", SCENES)
def test_ccx_variant_states_what_it_changes_and_why(scene):
    deck = ccx_scene_deck(scene, scene_mapping(FE, scene), NX, NY, t_end=2e-3, dt=1e-6)
    head = "\n".join(line for line in deck.splitlines() if line.startswith("**"))
    for reason in ("no analytical rigid surface", "penalty contact only", "no slip-rate-dependent friction"):
        assert reason in head
    parsed = read_deck(deck)
    assert parsed.friction == ((0.4, parsed.friction[0][1]),)  # one mu and its stick slope
    pair = next(h for h, _ in parsed.blocks if h.upper().startswith("*CONTACT PAIR"))
    assert _params(pair)["TYPE"] == "NODE TO SURFACE"


@pytest.mark.parametrize("scene", SCENES)
def test_abaqus_scene_deck_uses_only_documented_keyword_values(scene):
    deck = read_deck(scene_deck(scene, scene_mapping(FE, scene), FrictionTable.paper_fig17(), NX, NY))
    for head, _ in deck.blocks:
        keyword = "*" + head.lstrip("*").split(",")[0].strip().upper()
        assert keyword in DOCUMENTED, f"{scene}: {keyword} is not in the documented table"
        allowed = DOCUMENTED[keyword]
        for name, value in _params(head).items():
            assert name in allowed, f"{scene}: {keyword} has no documented parameter {name}"
            if allowed[name] is not None:
                assert value.upper() in allowed[name], f"{scene}: {keyword}, {name}={value} is not documented"


@pytest.mark.parametrize("scene", SCENES)
def test_abaqus_scene_deck_requests_contact_and_energy_history(scene):
    mapping = scene_mapping(FE, scene)
    text = scene_deck(scene, mapping, FrictionTable.paper_fig17(), NX, NY)
    deck = read_deck(text)
    heads = [h.upper().replace(" ", "") for h, _ in deck.blocks]
    values = [{v.strip() for line in d for v in line.split(",")} for _, d in deck.blocks]
    history = next(i for i, h in enumerate(heads) if h.startswith("*OUTPUT,HISTORY"))
    field = next(i for i, h in enumerate(heads) if h.startswith("*OUTPUT,FIELD"))
    requested = dict(zip(heads[history:field], values[history:field]))
    assert set(CONTACT_TOTALS) == requested["*CONTACTOUTPUT,SLAVE=LOWER,MASTER=DISC"] == {"CFN", "CFS"}
    assert set(CONTACT_NODE_VARIABLES) <= requested["*CONTACTOUTPUT,SLAVE=LOWER,MASTER=DISC,NSET=NODE1"]
    assert set(ENERGY_VARIABLES) <= requested["*ENERGYOUTPUT"]
    assert {"ALLKE", "ALLIE", "ALLFD", "ALLWK", "ETOTAL"} <= requested["*ENERGYOUTPUT"]
    assert {"U1", "U2", "V1", "V2"} <= requested["*NODEOUTPUT,NSET=NODE1"]
    assert heads[field + 1] == "*CONTACTOUTPUT,SLAVE=LOWER,MASTER=DISC,NSET=NODE1"
    assert values[field + 1] == {"CSTATUS"}
    head = "\n".join(line for line in text.splitlines() if line.startswith("**"))
    stated_choices = ("NLGEOM=YES", "BULK VISCOSITY", "b1 = 0.06", "b2 = 1.2", "DAMPING", "FRICTION", "UNITS")
    for stated in (*stated_choices, "MECHANICAL CONSTRAINT"):
        assert stated in head, f"{scene}: the header does not state {stated}"
    assert f"BETA = {mapping['solver']['stiffness_damping']:g}" in head


@pytest.mark.parametrize(
    "bad,key",
    [
        ({"dt": 2e-3}, "dt"),  # longer than t_end
        ({"dt": 0.0}, "dt"),
        ({"alpha": 0.5}, "alpha"),  # outside ccx's HHT range [-1/3, 0]
        ({"output_every": 0}, "output_every"),
        ({"mu": -0.1}, "mu"),
        ({"penalty_stiffness": float("inf")}, "penalty_stiffness"),
    ],
)
def test_a_bad_deck_argument_is_refused_naming_it_before_any_deck_is_written(bad, key):
    scene = SCENES[0]
    with pytest.raises(ValueError, match=rf"^{key}: "):
        ccx_scene_deck(scene, scene_mapping(FE, scene), NX, NY, **{"t_end": 1e-3, "dt": 1e-6, **bad})
