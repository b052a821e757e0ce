"""Broken config values and files are rejected before any job runs (stickslip.pipeline.config), with a
message naming the key (and its file and line); run with ``-s`` to see each input and its message."""

import shutil
import time

import pytest
from bad_inputs import ALIAS_BOMB, BAD_FILES, CASES, PRODUCIBLE, base_config

from stickslip.pipeline.config import ConfigError, load_config, merge, validate_config

from project_run import ROOT


@pytest.mark.parametrize("case", sorted(CASES))
def test_broken_config_is_rejected_naming_its_key(case):
    override, words = CASES[case]
    with pytest.raises(Exception) as info:  # noqa: B017 - schema errors are Snakemake's WorkflowError
        validate_config(merge(base_config(), override), producible=PRODUCIBLE)
    text = str(info.value)
    print(f"\n[{case}] {override}\n{text[-600:]}")
    for word in words:
        assert word in text, f"{case}: message does not name {word!r}:\n{text[-3000:]}"


def test_an_alias_bomb_is_refused_quickly_with_a_short_message(tmp_path):
    config_dir = tmp_path / "config"
    shutil.copytree(ROOT / "config", config_dir)
    (config_dir / "zz_extra.yaml").write_text(ALIAS_BOMB)
    start = time.process_time()
    with pytest.raises(ConfigError) as info:
        load_config(sorted(config_dir.glob("*.yaml")))
    # measured: ~0.1 s of CPU on this machine; the expansion itself takes ~60 s and gigabytes
    assert time.process_time() - start < 5.0
    assert len(str(info.value)) < 1000, str(info.value)


def test_a_huge_value_in_a_real_key_is_named_in_a_short_message():
    override = {"onedof": {"defaults": {"t_end": ["x" * 100] * 10_000}}}
    with pytest.raises(ConfigError) as info:
        validate_config(merge(base_config(), override), producible=PRODUCIBLE)
    assert "onedof.defaults.t_end" in str(info.value) and len(str(info.value)) < 1000, str(info.value)[:2000]


def _line_of(path, text):
    return next(i for i, line in enumerate(path.read_text().splitlines(), 1) if text in line)


def test_a_config_error_names_the_file_and_line_of_its_key(tmp_path):
    files = sorted((ROOT / "config").glob("*.yaml"))
    config = load_config(files)
    config["onedof"]["defaults"]["params"]["mass"] = -1.0
    with pytest.raises(ConfigError) as info:
        validate_config(config, producible=PRODUCIBLE, sources=files)
    mass_line = _line_of(ROOT / "config" / "config.yaml", "mass:")
    assert str(info.value).startswith(f"{ROOT / 'config' / 'config.yaml'}:{mass_line}: onedof.defaults"), info
    # a key an override file sets is located in that file (the later file wins)
    override = tmp_path / "override.yaml"
    override.write_text("# a comment\nfe:\n  sweeps:\n    angle_sweep:\n      parameter: contact.angel_deg\n")
    with pytest.raises(ConfigError) as info:
        validate_config(load_config([*files, override]), producible=PRODUCIBLE, sources=[*files, override])
    assert str(info.value).startswith(f"{override}:5: fe.sweeps.angle_sweep.parameter"), info


@pytest.mark.parametrize("small", [False, True], ids=["default", "small"])
def test_the_repository_config_passes_and_comes_back_typed(small):
    from stickslip.schema import PipelineConfig

    config = base_config(small)
    typed = validate_config(config, producible=PRODUCIBLE)
    assert isinstance(typed, PipelineConfig)  # what validation hands on: the values given, not defaults
    assert typed.fe.defaults.solver.initial_state == config["fe"]["defaults"]["solver"]["initial_state"]
    assert set(typed.onedof.scenes) == set(config["onedof"]["scenes"])
    assert typed.claims.readings == config["claims"]["readings"]


@pytest.mark.parametrize("case", sorted(BAD_FILES))
def test_a_config_file_that_is_not_data_is_rejected_naming_file_and_line(case, tmp_path):
    name, text, words = BAD_FILES[case]
    config_dir = tmp_path / "config"
    shutil.copytree(ROOT / "config", config_dir)
    (config_dir / name).write_text(text)
    with pytest.raises(ConfigError) as info:
        load_config(sorted(config_dir.glob("*.yaml")))
    for word in words:
        assert word in str(info.value), f"{case}: message does not name {word!r}: {info.value}"
