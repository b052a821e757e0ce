"""Dense maps (issue 7): config -> chunks -> one merged dataset; chunking never changes a number."""

import json

import numpy as np
import pytest
import xarray as xr

from stickslip.analysis.sweep import align_chunks, chunk_dataset, chunk_points, merge_chunks, run_points
from stickslip.pipeline.config import ConfigError, validate_config
from stickslip.pipeline.config import load_config as load_files
from stickslip.schema import PipelineConfig
from stickslip.studies.specs import dense_map as resolved_map

from project_run import ROOT, copy_project, run_snakemake


def load_config(*names):
    """The pipeline config as Snakemake merges it: config/*.yaml, then the given overrides."""
    return load_files(
        sorted((ROOT / "config").glob("*.yaml")) + [ROOT / "config" / "test" / n for n in names]
    )


def small_config(**changes):
    config = load_config("onedof.yaml", "dense_map.yaml")
    config["dense_map"].update(changes)
    return config


def dense_map(config, name):
    """``dense_map.maps.<name>`` of a config mapping, as the map's jobs resolve it (typed first)."""
    typed = PipelineConfig.model_validate(config)
    return resolved_map(typed.onedof, typed.dense_map, name)


def build(dm, chunk_size):
    parts = []
    for c in range(-(-dm.points // chunk_size)):
        res = dm.run(chunk_points(dm.axes, chunk_size, c))
        parts.append(chunk_dataset(dm.axes, chunk_size, c, res))
    return merge_chunks(dm.axes, align_chunks(parts))


def test_default_map_is_the_consistent_reading_with_caption_sigma_and_exact_solver():
    dm = dense_map(load_config(), "speed_damping")
    assert dm.spec.variant == "consistent" and dm.spec.params.sigma == 0.5
    assert dm.spec.solver_settings["solver"] == "exact"
    assert [a.name for a in dm.axes] == ["belt_velocity", "damping"]
    assert dm.chunks == -(-dm.points // dm.chunk_size)


def test_chunked_map_equals_unchunked_and_single_runs():
    dm = dense_map(small_config(), "speed_damping")
    assert dm.chunks == 3  # 12 points in chunks of 5: the last one is short
    whole, chunked = build(dm, dm.points), build(dm, dm.chunk_size)
    xr.testing.assert_identical(whole, chunked)
    assert whole.stick_fraction.dims == ("belt_velocity", "damping")
    single = run_points(
        dm.spec.params.with_(belt_velocity=0.9, damping=2.5),
        dm.spec.variant,
        [{}],
        dm.spec.solver(),
        dm.spec.t_end,
        dm.spec.t_eval,
        dm.spec.transient,
        dm.spec.count_window,
    )
    for name in ("stick_fraction", "amplitude_peak_to_peak", "frequency_peaks"):
        np.testing.assert_equal(float(whole[name].sel(belt_velocity=0.9, damping=2.5)), single[name][0])


def test_a_chunk_of_failed_runs_merges_as_nan():
    dm = dense_map(small_config(), "speed_damping")
    good = build(dm, dm.points)
    flat = [
        chunk_dataset(
            dm.axes,
            6,
            c,
            run_points(
                dm.spec.params,
                dm.spec.variant,
                chunk_points(dm.axes, 6, c),
                dm.spec.solver(),
                2.0,
                np.linspace(0, 2, 21),
                0.5,
            ),
        )
        for c in range(2)
    ]
    failed = flat[1][["solver_ok"]].copy()
    failed["solver_ok"][:] = 0.0
    merged = merge_chunks(dm.axes, align_chunks([flat[0], failed]))
    assert set(merged.data_vars) == set(good.data_vars)
    assert merged.stick_fraction.attrs["units"] == "1"
    assert np.isnan(merged.stick_fraction.values.ravel()[6:]).all()
    assert (merged.solver_ok.values.ravel()[6:] == 0).all()


TABLE = ["results/onedof/friction_mu_vr.csv"]  # written by a rule: need not exist before a run


@pytest.mark.parametrize("value", [0, -3, 2.5, "ten", True])
def test_bad_chunk_size_names_the_key(value):
    with pytest.raises(ConfigError, match=r"dense_map\.chunk_size"):
        validate_config(small_config(chunk_size=value), producible=TABLE)


def test_chunk_size_making_too_many_jobs_names_the_key():
    with pytest.raises(ConfigError, match=r"dense_map\.chunk_size: 1 points per chunk make 12 jobs"):
        validate_config(small_config(chunk_size=1, max_chunks=10), producible=TABLE)


@pytest.mark.parametrize(
    "axis, match",
    [
        ({"name": "dampening", "values": [1.0]}, r"axes\[0\]\.name: 'dampening' is not a parameter"),
        ({"name": "damping", "start": -1.0, "stop": 1.0, "num": 3}, r"axes\[0\] \(damping = -1\): damping"),
        ({"name": "damping", "start": 0.1, "stop": 1.0}, r"axes\[0\]\.num: missing"),
        (
            {"name": "damping", "start": 0.0, "stop": 1.0, "num": 3, "spacing": "log"},
            r"axes\[0\]: log spacing",
        ),
        (
            {"name": "damping", "values": [1.0], "linked": {"normal_farce": 1.0}},
            r"axes\[0\]\.linked: 'normal_farce'",
        ),
    ],
)
def test_bad_axis_names_the_key(axis, match):
    config = small_config()
    config["dense_map"]["maps"]["speed_damping"]["axes"] = [axis]
    with pytest.raises(ConfigError, match=r"dense_map\.maps\.speed_damping\." + match):
        validate_config(config, producible=TABLE)


def test_an_axis_swept_twice_names_the_key():
    config = small_config()
    axes = config["dense_map"]["maps"]["speed_damping"]["axes"]
    axes.append(dict(axes[0]))
    with pytest.raises(ConfigError, match=r"speed_damping\.axes\[2\]\.name: 'belt_velocity' is swept twice"):
        validate_config(config, producible=TABLE)


# --- through Snakemake -------------------------------------------------------------------------------------

TARGET = "results/figures/dense_map/speed_damping.png"


def snakemake_args(work, *extra):
    configs = [str(work / "config" / "test" / n) for n in ("onedof.yaml", "dense_map.yaml")]
    return ["--configfile", *configs, *extra]


@pytest.fixture(scope="module")
def project(tmp_path_factory):
    return copy_project(tmp_path_factory.mktemp("dense_map"))


@pytest.mark.pipeline
def test_pipeline_merged_map_has_dims_coords_units_and_equals_one_chunk_run(project, tmp_path):
    run_snakemake(project, *snakemake_args(project), "--", TARGET)
    chunked = xr.load_dataset(project / "results" / "dense_map" / "speed_damping.nc")
    assert (project / TARGET).stat().st_size > 0
    assert not list((project / "results" / "dense_map" / "chunks").rglob("*.nc"))  # temp() chunks removed
    assert (
        len(list((project / "results" / "benchmarks" / "dense_map_chunk" / "speed_damping").glob("*.tsv")))
        == 3
    )
    assert dict(chunked.sizes) == {"belt_velocity": 4, "damping": 3}
    np.testing.assert_allclose(chunked.damping.values, [0.5, 1.5, 2.5])
    assert chunked.belt_velocity.attrs == {"units": "mm s-1", "long_name": "belt velocity V_b"}
    assert chunked.damping.attrs["units"] == "N s mm-1"
    assert chunked.amplitude_peak_to_peak.attrs["units"] == "mm"
    assert chunked.stick_fraction.dims == ("belt_velocity", "damping")
    assert json.loads(chunked.attrs["interpretation"])["variant"] == "consistent"
    assert chunked.attrs["method_solver"] == "exact" and chunked.attrs["scene_damping"].startswith("swept")
    assert chunked.attrs["method_chunks"] == 3 and chunked.attrs["Conventions"].startswith("CF-")
    assert (chunked.solver_ok == 1).all()

    # one chunk, in a copy of its own (a results folder holds the build of one configuration)
    one_chunk = copy_project(tmp_path)
    (one_chunk / "one_chunk.yaml").write_text("dense_map:\n  chunk_size: 12\n")
    args = snakemake_args(one_chunk, str(one_chunk / "one_chunk.yaml"))
    run_snakemake(one_chunk, *args, "--", "results/dense_map/speed_damping.nc")
    whole = xr.load_dataset(one_chunk / "results" / "dense_map" / "speed_damping.nc")
    assert whole.attrs["method_chunks"] == 1
    xr.testing.assert_equal(whole, chunked)  # data, dims, coords and variable attrs


#: A stick shorter than this is a graze (round-off length), far below the output interval (0.01 s).
GRAZE = 1e-9


def with_law(config, law, method="switch"):
    maps = config["dense_map"]["maps"]
    maps["with_law"] = {**maps["speed_damping"], "method": method, "law": law}
    return config


def test_a_map_with_the_readings_own_affine_law_matches_the_exact_map():
    """Issue 13 item 6: a map accepts any friction law. Given the reading's own affine law (mu_s 0.5,
    sigma 0.5), the switch-solver map must reproduce the exact solver's map of the same grid."""
    config = with_law(small_config(), {"kind": "affine", "mu_s": 0.5, "sigma": 0.5})
    exact, switch = dense_map(config, "speed_damping"), dense_map(config, "with_law")
    assert switch.law is not None and switch.spec.solver_settings["solver"] == "switch"
    a, b = build(exact, exact.points), build(switch, switch.points)
    assert int(a.solver_ok.sum()) == a.solver_ok.size and int(b.solver_ok.sum()) == b.solver_ok.size
    for name in ("amplitude_peak_to_peak", "stick_fraction", "frequency_peaks"):
        np.testing.assert_allclose(b[name].values, a[name].values, rtol=1e-6, atol=1e-9, err_msg=name)
    # At C = sigma mu_s N (the grid's damping 2.5) the slip phase is undamped: the orbit only grazes v_r = 0,
    # once a period. Each graze is a stick of zero length (~1e-16 s), and whether a solver registers a given
    # graze is decided by round-off (machine-dependent), which splits or merges slip intervals. There the
    # interval means are not comparable; both solvers must still see a grazing orbit, not a finite stick.
    grazing = a.stick_time.values < GRAZE
    assert grazing.any(), "the grid no longer has a grazing point: this branch of the test is dead"
    assert np.all(b.stick_time.values[grazing] < GRAZE)
    for name in ("stick_time", "slip_time"):
        np.testing.assert_allclose(
            b[name].values[~grazing], a[name].values[~grazing], rtol=1e-6, atol=1e-9, err_msg=name
        )


def test_a_nonlinear_law_changes_the_map():
    config = with_law(small_config(), {"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3, "v_s": 0.5})
    affine = build(dense_map(config, "speed_damping"), 12)
    stribeck = build(dense_map(config, "with_law"), 12)
    assert not np.allclose(stribeck.amplitude_peak_to_peak.values, affine.amplitude_peak_to_peak.values)


@pytest.mark.parametrize(
    "law, method, words",
    [
        ({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3, "v_s": 0.5}, "exact", ["with_law.method", "switch"]),
        ({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3}, "switch", ["with_law.law.v_s"]),
        ({"kind": "coulomb", "mu_s": 0.3, "mu_k": 0.5}, "switch", ["with_law.law.mu_k"]),
    ],
)
def test_a_bad_law_or_method_is_rejected_naming_its_key(law, method, words):
    with pytest.raises(ConfigError) as info:
        validate_config(with_law(small_config(), law, method), producible=TABLE)
    for word in words:
        assert word in str(info.value), str(info.value)
