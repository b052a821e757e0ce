"""CalculiX (ccx) as a peer of the continuum strip: the three-way agreement on the config's strip, ccx's
output parsed, and the failures (ccx missing, a deck ccx refuses) named.

The tests that run ccx skip, naming why, only when ccx is missing outside CI; under CI=true a missing ccx
fails them (.ci/run installs Debian's calculix-ccx)."""

import numpy as np
import pytest
import yaml

from stickslip.fe.abaqus_deck import friction_table_of, read_deck, scene_deck
from stickslip.fe.params import BeamParams, FrictionTable
from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import scene_mapping
from stickslip.studies.fe_peer import MODELS, PAIRS, QUANTITIES, closed_form_values, peer_study
from stickslip.validation.calculix import CalculixError, parse_dat, run_ccx, static_block

from project_run import ROOT, require_ccx

FE = Fe.model_validate(yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"])
#: the strip the peer study solves (fe.defaults.beam)
STRIP = BeamParams.from_mapping(FE.defaults.beam.model_dump(exclude_none=True))


@pytest.fixture(scope="module")
def peer(tmp_path_factory):
    require_ccx()
    return peer_study(STRIP, FE.peer, workdir=tmp_path_factory.mktemp("ccx"))


def test_closed_form_continuum_and_calculix_agree_within_the_config_tolerance(peer):
    rows, ds, _ = peer
    tolerance = FE.peer.tolerance
    assert [r["quantity"] for r in rows] == list(QUANTITIES)
    for r in rows:
        for a, b in PAIRS:
            assert abs(r[a] - r[b]) <= tolerance * abs(r[b]), (r["quantity"], a, b, r[a], r[b])
        assert r["within_tolerance"]
    worst = max(abs(r[f"rel_diff_{a}_{b}"]) for r in rows for a, b in PAIRS)
    assert float(ds["max_abs_rel_diff"]) == worst <= tolerance
    assert int(ds["peers_agree"]) == 1


def test_the_closed_forms_are_the_config_strips_and_the_decks_carry_its_material(peer):
    """The closed-form column is the config's strip (and moves with it: twice the thickness, twice the
    frequencies), and the decks ccx ran hold the config's E, nu and rho."""
    rows, _, _ = peer
    beam = STRIP
    closed = closed_form_values(beam)
    for r in rows:
        assert r["closed_form"] == closed[r["quantity"]]
    thick = closed_form_values(STRIP.model_copy(update={"thickness": 2.0}))
    assert thick["free_f1"] == pytest.approx(2 * closed["free_f1"], rel=1e-12)
    assert closed["propped_f1"] == pytest.approx(366.39, abs=0.01)  # the documented closed form
    for deck in peer[2].values():
        lines = deck.splitlines()
        assert [float(v) for v in lines[lines.index("*ELASTIC") + 1].split(",")] == [
            beam.E,
            beam.poisson_ratio,
        ]
        assert float(lines[lines.index("*DENSITY") + 1]) == pytest.approx(beam.rho, rel=1e-11)


def test_peer_dataset_round_trips_with_every_quantity_and_model(peer, tmp_path):
    _, ds, decks = peer
    path = write_dataset(ds, tmp_path / "peer.nc", scene={}, interpretation="test", method={})
    back = read_dataset(path)
    for q, (unit, _) in QUANTITIES.items():
        for m in MODELS:
            assert back[f"{q}_{m}"].attrs["units"] == unit
            assert np.isfinite(float(back[f"{q}_{m}"]))
    assert list(back["quantity"].values) == list(QUANTITIES)
    assert set(decks) == {"peer_free", "peer_propped"}


DAT = """
     E I G E N V A L U E   O U T P U T

 MODE NO    EIGENVALUE                       FREQUENCY
                                     REAL PART            IMAGINARY PART
                           (RAD/TIME)      (CYCLES/TIME     (RAD/TIME)

      1   0.2761573E+06   0.5255067E+03   0.8363699E+02   0.0000000E+00
      2   0.1083931E+08   0.3292311E+04   0.5239876E+03   0.0000000E+00

     P A R T I C I P A T I O N   F A C T O R S

                    E I G E N V A L U E    N U M B E R     1

 displacements (vx,vy,vz) for set TIPLOW and time  0.1000000E+01

       101 -1.554742E+01 -2.257855E+03  0.000000E+00
"""

STATIC = """
 displacements (vx,vy,vz) for set TIPLOW and time  0.1000000E+01

       101  4.576882E-05  0.000000E+00  0.000000E+00
       303  4.576766E-05  0.000000E+00 -4.720645E-09

 total force (fx,fy,fz) for set PROP and time  0.1000000E+01

        1.012741E-15  2.867186E-03  6.232599E-05
"""


def test_parse_dat_reads_frequencies_mode_tables_and_static_tables():
    dat = parse_dat(STATIC + DAT)
    assert dat.frequencies == [[83.63699, 523.9876]]
    assert static_block(dat, "displacements", "TIPLOW", "s")[303] == (4.576766e-05, 0.0, -4.720645e-09)
    assert static_block(dat, "total force", "PROP", "s")[0][1] == 2.867186e-03
    modal = [b for b in dat.blocks if b.mode == 1]
    assert len(modal) == 1 and modal[0].rows[101][1] == -2.257855e03
    with pytest.raises(CalculixError, match="scene-x: the .dat has no static 'forces' table for node set"):
        static_block(dat, "forces", "PROP", "scene-x")


def test_a_missing_ccx_is_an_error_naming_ccx_its_package_and_the_scene(monkeypatch):
    monkeypatch.setenv("PATH", "")
    with pytest.raises(CalculixError, match=r"peer_free: the CalculiX solver 'ccx' is not on PATH.*-ccx"):
        peer_study(STRIP, FE.peer)


def test_ccx_stops_on_a_scene_deck_and_the_error_names_the_scene(tmp_path):
    """What ccx cannot run of the paper's model: its 2-D analytical rigid disc (*SURFACE, TYPE=SEGMENTS;
    *RIGID BODY, ANALYTICAL SURFACE) and ABAQUS/Explicit's *DYNAMIC, EXPLICIT data line, even with the
    friction reduced to one coefficient and a step of one microsecond. ccx exits with status 0 or not;
    either way the run is a CalculixError naming the scene and quoting ccx."""
    require_ccx()
    scene = "section9_kinematic_0p5mm_s"
    mapping = scene_mapping(FE, scene)
    mapping["solver"] = {**mapping["solver"], "t_end": 1e-6}
    deck = scene_deck(scene, mapping, FrictionTable.paper_fig17(), 100, 1, constant_mu=0.5)
    with pytest.raises(CalculixError, match=rf"{scene}: ccx failed .*unknown surface type"):
        run_ccx(deck, scene, workdir=tmp_path)
    assert (tmp_path / f"{scene}.inp").read_text() == deck


@pytest.mark.pipeline
def test_the_pipeline_writes_the_peer_and_one_deck_per_scene_with_the_fig17_table(tmp_path_factory):
    """The small CI build: results/fe/peer_calculix.nc says the three agree, and results/fe/inp/ holds one
    deck per Section 9-12 scene whose friction data is the run's own Fig. 17 table."""
    require_ccx()
    from project_run import shared_small_run

    work = shared_small_run(tmp_path_factory)
    ds = read_dataset(work / "results" / "fe" / "peer_calculix.nc")
    assert int(ds["peers_agree"]) == 1 and float(ds["max_abs_rel_diff"]) <= FE.peer.tolerance
    fig17 = FrictionTable.from_csv(work / "results" / "onedof" / "friction_mu_vr.csv")
    decks = sorted(p.stem for p in (work / "results" / "fe" / "inp").glob("*.inp"))
    # each scene's ABAQUS deck and its CalculiX variant (stickslip.fe.ccx_deck)
    scenes = list(FE.scenes)
    assert decks == sorted(scenes + [f"{s}_ccx" for s in scenes] + ["peer_free", "peer_propped"])
    for scene in FE.scenes:
        deck = read_deck((work / "results" / "fe" / "inp" / f"{scene}.inp").read_text())
        assert friction_table_of(deck) == fig17, scene
