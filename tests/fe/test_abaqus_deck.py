"""The ABAQUS-style decks (stickslip.fe.abaqus_deck) read back: keywords, node and element counts and
coordinates equal to the continuum model's, material, boundary conditions, the disc's placement and turning,
and the friction data equal to the table the scenes use (no solver needed)."""

import math

import numpy as np
import pytest
import yaml

from stickslip.fe.abaqus_deck import (
    brick_strip,
    disc_geometry,
    friction_table_of,
    linear_deck,
    read_deck,
    scene_deck,
)
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import scene_mapping
from stickslip.studies.fe_continuum import continuum_scene_from_mapping

from project_run import ROOT

BEAM = BeamParams()
FE = Fe.model_validate(yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"])
SCENES = list(FE.scenes)
#: a friction table of the Fig. 17 kind with irregular speeds (what the CSV of rule friction_table holds)
TABLE = FrictionTable((0.0, 0.021968952, 0.094, 0.6, 1.506563), (0.5, 0.4945, 0.4765, 0.3, 0.1233592))


def blocks(deck, keyword):
    return [data for head, data in deck.blocks if head.upper().startswith(keyword)]


def hex_volume(xyz):
    """Volume of a brick with nodes 1-4 on one face and 5-8 above them (positive if ordered as C3D8)."""
    a, b, d, e = xyz[0], xyz[1], xyz[3], xyz[4]
    return float(np.dot(np.cross(b - a, d - a), e - a))


@pytest.mark.parametrize("support", ["free", "propped"])
@pytest.mark.parametrize("nx, ny", [(100, 1), (7, 2)])
def test_linear_deck_has_the_continuum_mesh_extruded_once_through_the_width(support, nx, ny):
    deck = read_deck(linear_deck(BEAM, nx, ny, support, n_modes=5))
    assert set(deck.elements) == {"C3D8I"}
    assert len(deck.elements["C3D8I"]) == nx * ny
    assert len(deck.nodes) == 2 * (nx + 1) * (ny + 1)
    xyz = np.array([deck.nodes[i] for i in sorted(deck.nodes)])
    assert xyz[:, 0].min() == 0.0 and xyz[:, 0].max() == pytest.approx(BEAM.length, rel=1e-12)
    assert np.allclose(sorted(set(xyz[:, 1])), np.linspace(-0.5, 0.5, ny + 1) * BEAM.thickness)
    assert sorted(set(xyz[:, 2])) == [0.0, BEAM.width]
    volumes = [hex_volume(xyz[np.array(el) - 1]) for el in deck.elements["C3D8I"].values()]
    assert np.allclose(volumes, BEAM.length / nx * BEAM.thickness / ny * BEAM.width)
    steps = [k for k in deck.keywords if k in ("*STATIC", "*FREQUENCY")]
    assert steps == ["*STATIC", "*FREQUENCY"]
    assert blocks(deck, "*FREQUENCY") == [("5",)]
    elastic, density = blocks(deck, "*ELASTIC")[0][0], blocks(deck, "*DENSITY")[0][0]
    assert [float(v) for v in elastic.split(",")] == [BEAM.E, BEAM.poisson_ratio]
    assert float(density) == pytest.approx(BEAM.rho, rel=1e-11)
    bcs = [line.replace(" ", "") for data in blocks(deck, "*BOUNDARY") for line in data]
    assert {"CLAMP,1,3", "ZFACE,3,3"} <= set(bcs)
    assert ("PROP,2,2" in bcs) == (support == "propped")
    assert blocks(deck, "*DLOAD") == [("STRIP, GRAV, 9810., 0., -1., 0.",)]


def test_linear_deck_sets_name_the_free_end_corners():
    strip = brick_strip(BEAM, 100, 1)
    for ids, y in ((strip.tip_lower, -0.5), (strip.tip_upper, 0.5)):
        assert np.allclose(strip.nodes[ids - 1, :2], [BEAM.length, y])
    assert np.all(strip.nodes[strip.clamp - 1, 0] == 0.0) and strip.clamp.size == 4


def test_linear_deck_rejects_an_unknown_support():
    with pytest.raises(ValueError, match="support"):
        linear_deck(BEAM, 10, 1, "pinned")


@pytest.mark.parametrize("scene", SCENES)
def test_scene_deck_is_the_continuum_model_of_the_scene(scene):
    mapping = scene_mapping(FE, scene)
    nx, ny = FE.comparison.mesh
    deck = read_deck(scene_deck(scene, mapping, TABLE, nx, ny))
    model = continuum_scene_from_mapping(mapping, TABLE, nx, ny)
    assert len(deck.elements["CPS4R"]) == model.mesh.quads.shape[0] == nx * ny
    assert len(deck.nodes) == model.mesh.n_nodes + 1  # the strip and the disc's reference node
    xy = np.array([deck.nodes[i + 1] for i in range(model.mesh.n_nodes)])
    assert np.allclose(xy, model.mesh.nodes, rtol=0, atol=1e-9)
    assert np.allclose(deck.nodes[model.mesh.n_nodes + 1], model.disc_centre, rtol=0, atol=1e-9)
    for keyword in ("*SURFACE INTERACTION", "*FRICTION", "*RIGID BODY", "*CONTACT PAIR", "*DYNAMIC"):
        assert keyword in deck.keywords
    assert friction_table_of(deck) == TABLE
    bcs = [line.replace(" ", "") for data in blocks(deck, "*BOUNDARY") for line in data]
    assert ("UPPER,2,2" in bcs) == (mapping["contact"]["method"] == "fixed_normal")
    behaviour = "*SURFACE BEHAVIOR" in deck.keywords
    assert behaviour == (mapping["contact"]["method"] == "penalty")
    omega = float(next(line for line in bcs if line.startswith("DISCREF,6,6")).split(",")[3])
    disc = DiscParams.from_mapping(mapping["disc"])
    assert omega == pytest.approx(-disc.surface_speed / (disc.diameter / 2), rel=1e-10)  # clockwise
    (line,) = blocks(deck, "*DYNAMIC")[0]
    assert float(line.split(",")[1]) == float(mapping["solver"]["t_end"])


@pytest.mark.parametrize("angle", [0.0, 30.0])
def test_disc_profile_is_a_clockwise_circle_through_the_contact_corner(angle):
    contact = ContactParams(angle_deg=angle)
    disc = DiscParams(surface_speed_mm_s=0.5)
    mapping = {"beam": {}, "disc": {"surface_speed_mm_s": 0.5}, "contact": {"angle_deg": angle}}
    deck = read_deck(scene_deck("s", mapping, TABLE, 10, 1))
    (cx, cy), r, _ = disc_geometry(BEAM, disc, contact)
    profile = blocks(deck, "*SURFACE, TYPE=SEGMENTS")[0]
    points = [tuple(float(v) for v in line.split(",")[1:3]) for line in profile]
    assert points[0] == pytest.approx(points[-1])
    assert np.allclose([math.hypot(x - cx, y - cy) for x, y in points], r)
    assert min(math.hypot(x - BEAM.length, y + 0.5) for x, y in points) < 1e-9  # touches the lower corner
    angles = np.unwrap([math.atan2(y - cy, x - cx) for x, y in points])
    steps = np.diff(angles)
    assert np.all(steps < 0) and np.all(-steps < math.pi)  # clockwise, every arc below 180 degrees
    assert angles[0] - angles[-1] == pytest.approx(2 * math.pi)


def test_constant_mu_replaces_the_table_by_one_coefficient():
    mapping = {"beam": {}, "disc": {"surface_speed_mm_s": 0.5}}
    deck = read_deck(scene_deck("s", mapping, TABLE, 10, 1, constant_mu=0.4))
    assert deck.friction == ((0.4,),)
    assert friction_table_of(deck) == FrictionTable((0.0,), (0.4,))


def test_read_deck_refuses_data_before_any_keyword():
    with pytest.raises(ValueError, match="data line before any keyword"):
        read_deck("1, 0., 0.\n*NODE\n")
