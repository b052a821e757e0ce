"""The pipeline's configuration, checked in one place before any job runs.

``validate_config`` is what the Snakefile calls at parse time and what the bad-input tests call directly:
the typed models of ``stickslip.schema`` (types, physical ranges, finite numbers, unknown keys), then
what a model alone cannot see (names that refer to other sections, solver settings, every scene's model,
the friction table), each error naming the offending config key.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..io.typed_errors import typed_errors
from ..io.yaml_files import YamlFileError, key_location, load_yaml
from ..model.params import ParameterError

if TYPE_CHECKING:  # annotations only: the claims package and pydantic are imported when checked
    from ..claims.rows import Claim
    from ..schema import Inverse, MethodsStudy, PipelineConfig
    from ..schema.fe import Fe

__all__ = ["ConfigError", "typed_errors", "load_config", "merge", "drop_removed", "validate_config"]


class ConfigError(ValueError):
    """A config value is wrong; the message starts with its key (``section.sub.key: why``)."""


def merge(base: dict, override: dict) -> dict:
    """Recursive merge as Snakemake merges ``configfile``s: mappings merge, everything else is replaced."""
    out = dict(base)
    for key, value in override.items():
        out[key] = (
            merge(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
        )
    return out


def drop_removed(config: dict) -> dict:
    """Delete, in place and at any depth, every mapping entry whose value is null.

    Merging can only add or replace, so this is how an override file (``--configfile``) removes an entry
    of the main config: ``figures: {fig05: null}`` drops figure fig05, its rule and its outputs."""
    for key in [k for k, v in config.items() if v is None]:
        del config[key]
    for value in config.values():
        if isinstance(value, dict):
            drop_removed(value)
    return config


def load_config(paths: Iterable[str | Path]) -> dict:
    """The config Snakemake builds from these files, in order (later files override earlier ones; a null
    value removes an entry, see ``drop_removed``)."""
    config: dict = {}
    for path in paths:
        try:
            data = load_yaml(path) or {}
        except YamlFileError as exc:
            raise ConfigError(str(exc)) from None
        if not isinstance(data, dict):
            raise ConfigError(f"{path}: a config file is a mapping of sections, got {type(data).__name__}")
        config = merge(config, data)
    return drop_removed(config)


def located(message: str, sources: Sequence[str | Path]) -> str:
    """Every line of an error message that starts with a config key (``fe.scenes.x.beam.length: ...``)
    prefixed with the ``file:line`` of the config file that sets that key (``key_location``)."""
    out = []
    for line in message.splitlines():
        key = re.sub(r" \([^)]*\)", "", line.split(": ", 1)[0])
        where = key_location(key, sources) if re.fullmatch(r"[A-Za-z_][\w.\[\]-]*", key) else None
        out.append(f"{where}: {line}" if where else line)
    return "\n".join(out)


def validate_config(
    config: dict,
    *,
    producible: Iterable[str] = (),
    sources: Sequence[str | Path] = (),
    claims: Sequence[Claim] | None = None,
) -> PipelineConfig:
    """The config as one typed ``PipelineConfig``; ConfigError naming the key of the first bad value (all
    typed errors at once).

    ``producible`` lists files a rule writes (a friction table need not exist before the run); ``sources``
    the config files the config was loaded from, in order: each error line then starts with the file and
    line that set its key. ``claims``: the claim rows the caller has read already (``load_claims``), so
    the claims files are not read a second time; None reads the files ``inverse.claims_glob`` names."""
    try:
        return _validate(config, list(producible), claims)
    except ConfigError as exc:
        raise ConfigError(located(str(exc), sources)) from None


def _validate(config: dict, producible: list[str], claims: Sequence[Claim] | None = None) -> PipelineConfig:
    from pydantic import ValidationError

    from ..schema import PipelineConfig

    try:
        typed = PipelineConfig.model_validate(config)
    except ValidationError as exc:
        raise ConfigError(typed_errors(exc)) from None
    try:
        _check_onedof(typed)
        check_methods_config(typed.methods_study)
        from ..studies.fe_config import effective_fe

        check_fe_config(effective_fe(typed), list(producible), allow_expensive=typed.allow_expensive)
        from ..validation.setup import check as check_validation

        check_validation(typed.validation, list(producible))
        _check_inverse_claims(typed.inverse, claims)
    except ParameterError as exc:
        raise ConfigError(str(exc)) from None
    return typed


def _check_inverse_claims(inverse: Inverse, read: Sequence[Claim] | None = None) -> None:
    """Every claim the inverse study fits to is a claim of the files ``inverse.claims_glob`` names. ``read``:
    rows already read, each with its file; the glob's files are read here only when it names one that
    no row came from (or nothing was read)."""
    from glob import glob

    from ..inverse.problem import by_id, load_claim_rows

    files = {Path(p) for p in glob(inverse.claims_glob)}
    if read is None or not files <= {Path(c.file) for c in read}:
        # read as the inverse study reads them: every file of the glob together (ids unique across them)
        read = list(load_claim_rows(sorted(str(f) for f in files)).values())
    claims = by_id(c for c in read if Path(c.file) in files)
    for name, figure in inverse.figures.items():
        for claim in figure.claims:
            if claim not in claims:
                raise ConfigError(f"inverse.figures.{name}.claims: {claim!r} is not a claim id")


def _check_onedof(typed: PipelineConfig) -> None:
    """Every figure's runs, every sweep and critical-speed run for every claims reading and every dense
    map resolve."""
    from ..studies.specs import baseline_spec, dense_map, figure_runs, run_spec, sweep_spec

    onedof = typed.onedof
    for figure in onedof.figures.values():
        for scene, reading, method in figure_runs(figure):
            run_spec(onedof, scene, reading, method)
    for sweep in onedof.sweeps:
        for reading in typed.claims.readings:
            sweep_spec(onedof, sweep, reading)
    for reading in onedof.critical_speed.readings if onedof.critical_speed else []:
        baseline_spec(onedof, reading)
    for name in typed.dense_map.maps:
        dense_map(onedof, typed.dense_map, name)


#: Beam element-increments (elements x explicit steps) a build may run without ``allow_expensive: true``.
#: The default config's largest scene: 20 elements x ~1e5 steps = 2e6; ABAQUS's run of the paper (100
#: elements, 3.7e6 increments) is 3.7e8; the limit lets that through and stops a mesh typo 100x larger.
MAX_FE_ELEMENT_INCREMENTS = 2.0e9


def fe_layer_key(fe: Fe, scene: str, reading: str | None, dotted: str) -> str:
    """The config key that sets ``dotted`` (``solver.output_dt``) of a scene under a reading: the scene's own,
    else the reading's, else the defaults' (the layers of ``scene_mapping``)."""
    section, _, name = dotted.partition(".")
    layers = [(f"fe.scenes.{scene}", fe.scenes.get(scene))]
    if reading:
        layers.append((f"fe.readings.{reading}", fe.readings.get(reading)))
    layers.append(("fe.defaults", fe.defaults))
    for prefix, layer in layers:
        given = getattr(layer, section, None) if layer is not None else None
        if given is not None and name in given.model_fields_set:
            return f"{prefix}.{dotted}"
    return f"fe.scenes.{scene}.{dotted}"


def check_fe_lengths(fe: Fe, scene: str, reading: str, allow_expensive: bool = False) -> None:
    """A scene merged under a reading: its windows fit inside its run, it stores at most
    ``MAX_SAMPLES_PER_RUN`` samples (like a 1-DOF scene), and its estimated cost is within the guard: the
    explicit step is at most the time an axial wave needs to cross one element (the cheapest case), so
    elements x t_end / step is a lower bound of the work. An error names the key a value came from."""
    from ..fe.params import SolverParams
    from ..schema import MAX_SAMPLES_PER_RUN
    from ..studies.fe_config import scene_mapping

    mapping = scene_mapping(fe, scene, reading)
    solver, output, beam = mapping.get("solver", {}), mapping.get("output", {}), mapping.get("beam", {})
    where = f"fe.scenes.{scene} (FE reading {reading})"
    t_end = solver.get("t_end")
    if t_end is None:
        return
    checks = [("solver.output_dt", solver.get("output_dt")), ("output.bin_width", output.get("bin_width"))]
    checks += [(f"output.windows[{i}]", w[1]) for i, w in enumerate(output.get("windows") or [])]
    for name, value in checks:
        if value is not None and value > t_end:
            key = fe_layer_key(fe, scene, reading, name)
            raise ConfigError(f"{key}: {value!r} does not fit in solver.t_end = {t_end!r} ({where})")
    output_dt = solver.get("output_dt")
    if output_dt is not None and t_end / output_dt + 1 > MAX_SAMPLES_PER_RUN:
        raise ConfigError(
            f"{fe_layer_key(fe, scene, reading, 'solver.output_dt')}: {output_dt!r} stores "
            f"{t_end / output_dt + 1:.3g} samples over solver.t_end = {t_end!r} ({where}), more than the "
            f"limit {MAX_SAMPLES_PER_RUN:.3g} per run"
        )
    needed = ("n_elements", "length", "youngs_modulus_gpa", "density_kg_m3")
    if allow_expensive or any(beam.get(k) is None for k in needed):
        return
    wave_speed = (beam["youngs_modulus_gpa"] * 1e9 / beam["density_kg_m3"]) ** 0.5 * 1e3  # mm/s
    factor = SolverParams.from_mapping(solver).safety_factor  # the scene's step factor, its default included
    step = factor * beam["length"] / beam["n_elements"] / wave_speed
    cost = beam["n_elements"] * t_end / step
    if cost > MAX_FE_ELEMENT_INCREMENTS:
        raise ConfigError(
            f"{where}.beam.n_elements: {beam['n_elements']} elements over t_end = {t_end} s is an estimated "
            f"{cost:.3g} element-increments, more than the limit {MAX_FE_ELEMENT_INCREMENTS:.3g}; set "
            "allow_expensive: true to build it anyway"
        )


def check_fe_config(fe: Fe, producible: list[str], allow_expensive: bool = False) -> None:
    """Resolve every FE scene (merged over the defaults) and find the friction table, so a bad value fails
    before any job starts with the config key named (references between entries: stickslip.schema)."""
    from ..fe.params import SceneParams
    from ..studies.fe_config import scene_mapping

    for name in fe.scenes:
        for reading in fe.readings:
            check_fe_lengths(fe, name, reading, allow_expensive)
        mapping = scene_mapping(fe, name)
        try:
            SceneParams.from_mapping(mapping)
        except (ValueError, TypeError, KeyError) as exc:
            raise ConfigError(f"fe.scenes.{name}: {exc}") from None
    # the studies run their base scene over their own window: it must hold the scene's output sampling
    windows = [(f"fe.sweeps.{n}", sw.base, sw.t_end) for n, sw in fe.sweeps.items()]
    windows += [("fe.convergence", fe.convergence.base, fe.convergence.t_end)]
    windows += [(f"fe.comparison ({s})", s, fe.comparison.t_end) for s in fe.scenes]
    for key, base, t_end in windows:
        if t_end is None:
            continue
        mapping = scene_mapping(fe, base)
        for dotted in ("solver.output_dt", "output.bin_width"):
            section, _, field = dotted.partition(".")
            value = (mapping.get(section) or {}).get(field)
            if value is not None and value > t_end:
                raise ConfigError(
                    f"{key.split(' ')[0]}.t_end: {t_end!r} is shorter than {dotted} = {value!r} of its base "
                    f"scene {base} ({fe_layer_key(fe, base, None, dotted)})"
                )
    table = fe.friction_table
    if table not in producible and not Path(table).is_file():
        raise ConfigError(
            f"fe.friction_table: {table!r} does not exist and no rule writes it (rule friction_table writes "
            f"{producible})"
        )
    if table not in producible:  # a table of the user's: checked now, not by the first FE job
        check_friction_table(table, "fe.friction_table")


#: The header of a friction table (rule friction_table writes it; the FE scenes read it): the relative speed
#: in mm/s and the friction coefficient (no unit).
FRICTION_TABLE_COLUMNS = ("relative_velocity_mm_per_s", "mu")
#: A friction table larger than this is not one (a table has tens to thousands of rows).
FRICTION_TABLE_MAX_BYTES = 10 << 20


def check_friction_table(path, key: str) -> None:
    """A friction table file as the FE scenes read it: the header ``relative_velocity_mm_per_s,mu`` (the
    speed's unit is in its name), at least one row, every value a finite number, speeds >= 0 and increasing,
    mu >= 0. Raises ConfigError naming the key, the file and the line."""
    where = f"{key}: {str(path)!r}"
    expected = ",".join(FRICTION_TABLE_COLUMNS)
    try:
        if Path(path).stat().st_size > FRICTION_TABLE_MAX_BYTES:
            raise ConfigError(f"{where} is over {FRICTION_TABLE_MAX_BYTES} bytes: not a friction table")
        lines = Path(path).read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise ConfigError(f"{where} cannot be read as a friction table ({type(exc).__name__})") from exc
    rows = [(n, line) for n, line in enumerate(lines, 1) if line.strip()]
    header = rows[0][1].strip() if rows else ""
    if tuple(c.strip() for c in header.split(",")) != FRICTION_TABLE_COLUMNS:
        raise ConfigError(
            f"{where} is not a friction table: line 1 must be the header {expected!r} (relative speed in "
            f"mm/s, friction coefficient), got {header[:80]!r}"
        )
    if len(rows) < 2:
        raise ConfigError(f"{where}: the friction table has a header but no rows")
    speeds = []
    for n, line in rows[1:]:
        cells = line.split(",")
        try:
            speed, mu = (float(c) for c in cells) if len(cells) == 2 else (None, None)
        except ValueError:
            speed = mu = None
        if speed is None or not (math.isfinite(speed) and math.isfinite(mu)):
            raise ConfigError(f"{where} line {n}: expected two finite numbers ({expected}): {line[:80]!r}")
        if speed < 0 or mu < 0:
            raise ConfigError(f"{where} line {n}: speed and mu must be >= 0, got {line[:80]!r}")
        if speeds and speed <= speeds[-1]:
            raise ConfigError(
                f"{where} line {n}: the speeds must increase (relative_velocity_mm_per_s {speed!r} after "
                f"{speeds[-1]!r})"
            )
        speeds.append(speed)


def check_methods_config(study: MethodsStudy) -> None:
    """Build every scene model and every swept method of the methods study, so a bad value fails before
    any job starts with the config key named (what the schema cannot see: a scene's parameters together,
    an unknown solver setting)."""
    from ..solvers import make_solver
    from ..studies.methods import expand_methods, scene_model

    fm = study.failure_map
    runs = [(f"methods_study.scenes.{s}", s, {}) for s in study.scenes]
    runs += [
        (f"methods_study.failure_map.values[{i}]", fm.scene, {fm.parameter: v})
        for i, v in enumerate(fm.values)
    ]
    for key, scene, overrides in runs:
        try:
            scene_model(study, scene, **overrides)
        except (ValueError, TypeError) as exc:  # ParameterError among them
            raise ConfigError(f"{key} (with methods_study.base_params): {exc}") from None
    groups = [("methods", study.methods), ("failure_map.methods", fm.methods)]
    groups.append(("paper_method", [study.paper_method]))
    for key, entries in groups:  # every swept combination of settings, not only the fixed ones
        for solver, settings, label in expand_methods(entries):
            try:
                make_solver(solver, **settings)
            except (ValueError, TypeError, KeyError) as exc:
                raise ConfigError(f"methods_study.{key}: {label}: {exc}") from None
