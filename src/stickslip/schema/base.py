"""The config models' common ground: the mapping bases (unknown keys are errors), number types and the
cross-reference helpers every section uses."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, create_model
from pydantic.fields import FieldInfo

# the number types and the unit readings are the parameter sets' own (one home for every bound)
from ..model.params import Finite, Fraction, NonNegative, Positive, Units  # noqa: F401  (re-exported)

#: Jobs a dense map may be split into unless ``dense_map.max_chunks`` says otherwise.
DEFAULT_MAX_CHUNKS = 2000

#: Where the generated JSON schema lives (for editors, `snakemake --lint` readers and documentation).
SCHEMA_PATH = Path("workflow/schemas/config.schema.json")

Names = Annotated[list[str], Field(min_length=1)]
#: A reading of the paper's friction law (``stickslip.model.friction.VARIANTS``; a test keeps them equal).
Variant = Literal["eq3_printed", "eq4_printed", "consistent"]


def parameter_section(name: str, fields: dict[str, FieldInfo]) -> type[Section]:
    """The config section of a parameter set (its pydantic ``fields``): the same keys, types and bounds, each
    optional (a scene gives only what it changes; the set's default fills the rest)."""
    optional = {
        key: (
            (Annotated[f.annotation, *f.metadata] if f.metadata else f.annotation) | None,
            Field(None, description=f.description),
        )
        for key, f in fields.items()
    }
    return create_model(name, __base__=Section, __module__=__name__, **optional)


def belt_parameter(name: str) -> str:
    """``name`` is a parameter of the 1-DOF model (what a sweep or a map axis may set)."""
    import dataclasses

    from ..model.params import BeltParams

    known = {f.name for f in dataclasses.fields(BeltParams)} - {"units"}
    if name not in known:
        raise ValueError(f"{name!r} is not a parameter (known: {sorted(known)})")
    return name


def linked_parameters(linked: dict | None) -> dict | None:
    for name in linked or {}:
        belt_parameter(name)
    return linked


def needs_switch(key: str, law, method: str, methods: dict) -> None:
    """A friction law other than the readings' is solved by the switch solver only."""
    if law is not None and methods[method].solver != "switch":
        raise ValueError(
            f"{key}.method: a friction law needs a method whose solver is 'switch' (the exact solver handles "
            f"the readings' affine laws only), got {method!r}"
        )


def check_refs(refs, known: dict, section: str) -> None:
    """Every (key, name) in ``refs`` names an entry of ``known`` (the mapping at ``section``)."""
    for key, name in refs:
        if name not in known:
            raise ValueError(f"{key}: {name!r} is not an entry of {section} ({sorted(known)})")


def given(section: BaseModel | None) -> dict:
    """The values a config mapping sets, as a mapping: a key left out (None in the model) is absent, so
    the consumer's own default applies; no mapping: nothing set."""
    return section.model_dump(exclude_none=True) if section is not None else {}


def canonical(value):
    """A config value with every mapping's keys in sorted order (lists keep theirs: their order is meaning).

    Snakemake compares a job's params by their repr, where a dict shows its keys in the order the YAML file
    wrote them: a reordered key would re-run every job that reads it. The 1-DOF and map sections, the friction
    table's and the FE peer's go through here (so do the FE sections, in studies.fe_config.job_config), so
    those jobs depend on what the config says, not on how it is laid out. Left as written: sections whose
    order is meaning (the methods study's and validation's labels and law order, the inverse study's
    hypotheses, each named by its first key)."""
    if isinstance(value, Mapping):
        return {key: canonical(value[key]) for key in sorted(value, key=str)}
    if isinstance(value, (list, tuple)):
        return [canonical(item) for item in value]
    return value


def as_written(entry):
    """A typed config section as a job's params where the order of its entries is meaning (the methods
    study's and validation's labels and law order, the inverse study's hypotheses): the values it gave."""
    return entry.model_dump(exclude_unset=True)


def as_params(entry):
    """Typed config entries (one, or a mapping or list of them) as a job's params: the values the config
    gave, keys sorted (``canonical``); a job types them again at its boundary (stickslip.schema) and re-runs
    when one of these values changes."""
    if isinstance(entry, dict):
        return {key: as_params(value) for key, value in sorted(entry.items())}
    if isinstance(entry, (list, tuple)):
        return [as_params(item) for item in entry]
    dump = getattr(entry, "model_dump", None)
    return entry if dump is None else canonical(dump(exclude_unset=True))


class Section(BaseModel):
    """A config mapping: unknown keys are errors (a misspelt key must not be silently ignored)."""

    model_config = ConfigDict(extra="forbid", strict=True)  # no "5" for 5: YAML types are meant

    @classmethod
    def part_of(cls, mapping: dict) -> dict:
        """The entries of a config mapping this model reads: a job's params, when the job reads part of a
        section (Snakemake re-runs it when one of them changes, not when the rest does)."""
        return {key: mapping[key] for key in cls.model_fields if key in mapping}


class Open(BaseModel):
    """A mapping whose extra keys are settings checked elsewhere (solver settings: ``check_settings``)."""

    model_config = ConfigDict(extra="allow", strict=True)
