"""The config is validated once into one typed object, which is what validation hands on."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_validate_config_returns_the_typed_config_of_the_values_it_checked():
    from stickslip.catalogue import friction_table
    from stickslip.pipeline.config import load_config, validate_config
    from stickslip.pipeline.config_models import PipelineConfig

    config = load_config(sorted((ROOT / "config").glob("*.yaml")))
    typed = validate_config(config, producible=[friction_table()])
    assert isinstance(typed, PipelineConfig)
    # the typed object holds the values given, not defaults in their place
    assert typed.fe.defaults.solver.initial_state == config["fe"]["defaults"]["solver"]["initial_state"]
    assert set(typed.onedof.scenes) == set(config["onedof"]["scenes"])
    assert typed.claims.readings == config["claims"]["readings"]
