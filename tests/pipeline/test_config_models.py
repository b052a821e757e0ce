"""The typed config layer: the committed JSON schema is generated from the models (never written twice), and
the models' names are the code's own. That the repository's configs validate and that a bad value is rejected
naming its full key is checked through the one entry point, in test_config_errors.py."""

from stickslip.schema import SCHEMA_PATH, schema_text

from project_run import ROOT


def test_committed_schema_is_the_generated_one():
    assert (ROOT / SCHEMA_PATH).read_text() == schema_text(), (
        "workflow/schemas/config.schema.json is stale: run `python -m stickslip.schema --write`"
    )


def test_typed_names_are_the_models_own():
    """The typed layer's readings, unit readings and freeable inverse parameters are the ones the code
    implements (written twice only because a Literal type needs the values spelled out)."""
    from typing import get_args

    from stickslip.inverse.problem import PARAMS
    from stickslip.model.friction import VARIANTS
    from stickslip.schema import InverseParameter, Variant

    assert get_args(Variant) == VARIANTS
    assert get_args(InverseParameter) == PARAMS
