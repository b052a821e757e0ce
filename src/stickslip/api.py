"""Your own scenario in one call: a 1-DOF run or a beam-on-disc scene, computed as the pipeline computes it.

Both functions take the project's config (every ``config/*.yaml``, then overlays, as the Snakefile reads
them), add your changes as a config entry (a scene of their own), check the whole config with the typed
models (an unknown or bad value is a ``ConfigError`` naming its key) and call the same study function and
writer as the pipeline's script, so ``output=`` writes the dataset the pipeline would write.

>>> import stickslip
>>> ds = stickslip.simulate(mu_s=0.6, damping=1.0)
>>> ds.attrs["scene_mu_s"], ds.attrs["scene_damping"], ds.attrs["method_name"]
(0.6, 1.0, 'exact')
>>> round(float(ds.stick_velocity), 6)  # in stick the mass moves with the belt (0.5 mm/s)
0.5

Any friction law of ``stickslip.model.laws`` (the config's ``law:`` mapping); without a ``method`` a law runs
under the switch solver, the only one that integrates any law:

>>> ds = stickslip.simulate(law={"kind": "stribeck", "mu_k": 0.3, "v_s": 0.5}, t_end=20.0, transient=5.0)
>>> ds.attrs["method_name"], ds.attrs["scene_friction_law"]
('switch', 'StribeckLaw(mu_s=0.5, mu_k=0.3, v_s=0.5)')
>>> from stickslip.pipeline.config import ConfigError
>>> try:
...     stickslip.simulate(law={"kind": "stribeck", "mu_k": 0.3, "v_s": 0.5}, method="exact")
... except ConfigError as exc:
...     print(exc)
onedof.scenes.custom.law: a 'stribeck' friction law is solved by the 'switch' solver only;
method 'exact' uses 'exact'
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import xarray as xr

#: The name of the scene a call with changes runs (``onedof.scenes.custom``, ``fe.scenes.custom``).
CUSTOM = "custom"
#: Run-length keys of a 1-DOF scene (``studies.specs.RUN_LENGTHS``).
RUN_LENGTHS = ("t_end", "output_dt", "transient", "count_window")


def project_root(root: str | Path | None = None) -> Path:
    """The project folder: ``root``, else the working directory if it holds ``config/config.yaml``, else
    the checkout this package is installed from."""
    if root is not None:
        return Path(root)
    for candidate in (Path.cwd(), Path(__file__).resolve().parents[2]):
        if (candidate / "config" / "config.yaml").is_file():
            return candidate
    raise FileNotFoundError(
        "no project folder: run from the stickslip checkout (it holds config/config.yaml) or pass root="
    )


def load_project_config(configfiles: Sequence[str | Path] = (), root: str | Path | None = None) -> dict:
    """The config the Snakefile builds: every ``config/*.yaml`` of the project, then ``configfiles`` in
    order (a null removes an entry). Not yet validated.

    Built in the Snakefile's order, key order included: Snakemake reads the ``--configfile`` files first,
    then the Snakefile merges everything over them, so an overlay's keys come first in every mapping (the
    perturbation ensemble does not depend on it: its signs are drawn by run id and field path)."""
    from .io.yaml_files import load_yaml
    from .pipeline.config import drop_removed, load_config, merge

    base = project_root(root)
    overlays = [Path(p) for p in configfiles]
    config: dict = {}
    for path in overlays:  # what Snakemake's own --configfile loading gives the Snakefile
        config = merge(config, load_yaml(path) or {})
    config = merge(config, load_config(sorted((base / "config").glob("*.yaml")) + overlays))
    config = drop_removed(config)
    inverse = config.get("inverse") or {}
    if "claims_glob" in inverse and not Path(inverse["claims_glob"]).is_absolute():
        # a path of the project, wherever the command runs: the pipeline runs in the project folder
        config["inverse"] = {**inverse, "claims_glob": str(base.resolve() / inverse["claims_glob"])}
    return config


def _validated(config: dict) -> dict:
    """The whole config checked as the Snakefile checks it (a beam-on-disc run: scenes, readings, cost)."""
    from .catalogue import friction_table
    from .pipeline.config import validate_config

    validate_config(config, producible=[friction_table()])  # the one input that is some rule's output
    return config


def _validated_onedof(config: dict) -> dict:
    """The ``onedof`` section checked by its typed model (what a 1-DOF run reads; the whole config's check
    also resolves every FE scene and study, seconds a single run does not need)."""
    from pydantic import ValidationError

    from .io.typed_errors import typed_errors
    from .pipeline.config import ConfigError
    from .pipeline.config_models import Onedof

    try:
        Onedof.model_validate(config["onedof"])
    except ValidationError as exc:
        lines = [ln if ln.startswith("onedof.") else f"onedof.{ln}" for ln in typed_errors(exc).splitlines()]
        raise ConfigError("\n".join(lines)) from None
    return config


def _law_mapping(law, mu_s: float) -> dict | None:
    """A law as its config mapping; a law without ``mu_s`` takes the run's (every law but a table has one)."""
    if law is None:
        return None
    entry = dict(law.describe()) if hasattr(law, "describe") else dict(law)
    if entry.get("kind") not in ("tabulated", None) and "mu_s" not in entry:
        entry["mu_s"] = mu_s
    return entry


def onedof_scenario(
    config: dict,
    scene: str | None = None,
    *,
    law=None,
    run: Mapping | None = None,
    params: Mapping | None = None,
) -> tuple[dict, str]:
    """(config, scene name) with the changes as a scene of their own: ``onedof.scenes.custom`` = ``scene``
    (default: the baseline's) with ``params``, ``law`` and ``run`` lengths over it. Without changes the
    scene itself, so the run is the pipeline's run of that scene."""
    onedof = config["onedof"]
    scene = scene or onedof["baseline"]["scene"]
    if scene not in onedof["scenes"]:
        from .pipeline.config import ConfigError

        raise ConfigError(f"scene: {scene!r} is not an entry of onedof.scenes ({sorted(onedof['scenes'])})")
    params, run = dict(params or {}), dict(run or {})
    if not (params or run or law is not None):
        return config, scene
    base = copy.deepcopy(onedof["scenes"][scene])
    merged = {**(onedof["defaults"].get("params") or {}), **(base.get("params") or {}), **params}
    changes = ", ".join(f"{k}={v}" for k, v in {**params, **run}.items())
    entry = {
        **base,
        "figure": "",
        "description": f"scene {scene} with {changes or 'its own friction law'}",
        "params": {**(base.get("params") or {}), **params},
        **run,
    }
    law_entry = _law_mapping(law, merged.get("mu_s"))
    if law_entry is not None:
        entry["law"] = law_entry
        entry["description"] += f", friction law {law_entry['kind']}"
    config = copy.deepcopy(config)
    config["onedof"]["scenes"][CUSTOM] = entry
    return config, CUSTOM


def _ensemble_spec(config: dict, on: bool):
    from .ensemble import EnsembleSpec

    return EnsembleSpec.from_mapping(config.get("ensemble")).without_blas() if on else None


def simulate(
    scene: str | None = None,
    *,
    reading: str | None = None,
    method: str | None = None,
    law=None,
    t_end: float | None = None,
    output_dt: float | None = None,
    transient: float | None = None,
    count_window: float | None = None,
    ensemble: bool = False,
    output: str | Path | None = None,
    configfiles: Sequence[str | Path] = (),
    root: str | Path | None = None,
    config: dict | None = None,
    **params: float,
) -> xr.Dataset:
    """One 1-DOF run: time series, the paper's metrics (amplitude, frequency, stick and slip time, ...),
    the solver's status, and the provenance attributes the pipeline writes.

    As scipy's ``solve_ivp`` reports its outcome, the dataset's attributes ``status`` ("success",
    "diverged" or "failed"), ``success`` (0 only for a numerical failure) and ``message`` (the outcome and
    the mechanism behind it, e.g. why the motion grows without bound) say what the run did; a divergence is
    the model's answer, not an error. Every metric is there, NaN where the run defines none.

    ``scene``, ``reading`` and ``method`` are entries of ``onedof.scenes/readings/methods`` (default: the
    baseline's, ``onedof.baseline``; with a ``law`` the default method is ``switch``). ``params`` are the
    scene's parameters (``mass``, ``stiffness``, ``damping``, ``mu_s``, ``sigma``, ``normal_force``, ``x0``,
    ``v0``, ``belt_velocity``, ``belt_deceleration``, ``units``, ``plateau_speed``); ``law`` is a config
    mapping (``{"kind": "stribeck", "mu_k": 0.3, "v_s": 0.5}``; ``mu_s`` defaults to the run's) or a law of
    ``stickslip.model.laws``. ``ensemble`` adds the config's perturbation ensemble (``<metric>_ensemble``),
    built over this run's config. ``output`` writes the dataset with the pipeline's writer and returns it as
    read back (checksum verified). ``config``: the project config already loaded (``load_project_config``)
    instead of reading ``configfiles``. A bad value raises ``ConfigError`` naming its config key."""
    from .catalogue import onedof_dataset
    from .ensemble import ensemble_dataset
    from .studies.onedof import scene_run_dataset
    from .studies.specs import PERTURBED_FIELDS, run_spec

    config = config if config is not None else load_project_config(configfiles, root)
    baseline = config["onedof"]["baseline"]
    run = {
        k: v
        for k, v in zip(RUN_LENGTHS, (t_end, output_dt, transient, count_window), strict=True)
        if v is not None
    }
    config, name = onedof_scenario(config, scene, law=law, run=run, params=params)
    _validated_onedof(config)
    reading = reading or baseline["reading"]
    method = method or ("switch" if law is not None else baseline["method"])
    for key, value in (("reading", reading), ("method", method)):
        if value not in config["onedof"][key + "s"]:
            from .pipeline.config import ConfigError

            known = sorted(config["onedof"][key + "s"])
            raise ConfigError(f"{key}: {value!r} is not an entry of onedof.{key}s ({known})")
    try:
        spec = run_spec(config, name, reading, method)
    except ValueError as exc:
        from .pipeline.config import ConfigError

        raise ConfigError(str(exc)) from None
    ds = ensemble_dataset(  # signs drawn by name: the run's dataset path in the pipeline's catalogue
        lambda cfg: scene_run_dataset(run_spec(cfg, name, reading, method)),
        config,
        _ensemble_spec(config, ensemble),
        run_id=onedof_dataset(name, reading, method),
        fields=PERTURBED_FIELDS,
    )
    attrs = {
        "scene": spec.scene_attrs(),
        "interpretation": spec.interpretation(),
        "method": {"name": method, **spec.solver_settings, **ds.attrs.pop("solver_run_settings", {})},
        "title": f"{spec.figure} {name}: reading {reading}, method {method}",
    }
    return _finish(ds, attrs, output)


def _finish(ds: xr.Dataset, attrs: dict, output) -> xr.Dataset:
    """Write with the pipeline's writer and read back, or attach the same provenance in memory."""
    from .io.netcdf import provenance_attrs, read_dataset, write_dataset

    if output is not None:
        write_dataset(ds, output, **attrs)
        return read_dataset(output)
    prov = provenance_attrs(
        title=attrs.pop("title", None) or ds.attrs.get("title", ""),
        **{k: attrs[k] for k in ("scene", "interpretation", "method")},
    )
    ds.attrs = {**prov, **ds.attrs}
    return ds


def fe_scene_name(fe_cfg: Mapping, scene: str, speed: float | None = None) -> str:
    """A scene of ``fe.scenes`` by its name, or by its stem and a surface speed [mm/s]: ``section9_kinematic``
    with speed 0.5 is ``section9_kinematic_0p5mm_s``."""
    scenes = fe_cfg.get("scenes", {})
    if scene in scenes:
        return scene
    if speed is not None:
        name = f"{scene}_{speed:g}mm_s".replace(".", "p")
        if name in scenes:
            return name
    from .pipeline.config import ConfigError

    stems = sorted({s.rsplit("_", 2)[0] if s.endswith("mm_s") else s.rsplit("_", 1)[0] for s in scenes})
    raise ConfigError(
        f"fe.scenes.{scene}: no such scene (scenes: {sorted(scenes)}; or a stem {stems} with --speed "
        "matching a scene's mm/s suffix)"
    )


def simulate_fe(
    scene: str,
    *,
    speed: float | None = None,
    reading: str | None = None,
    model: str = "beam",
    t_end: float | None = None,
    ensemble: bool = True,
    progress: Callable[[str], Callable[[int, int], None]] | None = None,
    output: str | Path | None = None,
    friction_table: str | Path | None = None,
    configfiles: Sequence[str | Path] = (),
    root: str | Path | None = None,
) -> xr.Dataset:
    """One beam-on-disc scene (``fe.scenes``) under one FE reading (default: the first, the paper's
    geometry reading), as rule ``fe_reading`` computes it: with ``model="beam"`` and ``ensemble`` the
    perturbation ensemble and the step-halving check, so ``output`` equals the pipeline's
    ``results/fe/<reading>/<scene>.nc`` for the same config. ``model="continuum"`` runs the continuum strip
    of the model comparison (``fe.comparison.mesh``) on the scene instead. ``t_end`` [s] overrides the
    scene's window; ``progress(label)`` returns a ``(done, total)`` callback per run (time steps). The
    friction law is the Fig. 17 table (``fe.friction_table``, written by rule friction_table)."""
    from dataclasses import replace

    from . import catalogue as paths
    from .ensemble import EnsembleSpec, ensemble_dataset, step_member_values
    from .fe.params import FrictionTable
    from .fe.quantities import INTERPRETATION
    from .fe.step_halving import HALF_STEP, apply_step_halving
    from .pipeline.config import ConfigError
    from .studies.fe_config import PERTURBED_FIELDS, effective_fe_config, scene_mapping
    from .studies.fe_continuum import continuum_dataset
    from .studies.fe_scene import scene_dataset

    config = load_project_config(configfiles, root)
    name = fe_scene_name(config["fe"], scene, speed)
    if model not in ("beam", "continuum"):
        raise ConfigError(f"model: {model!r} is not one of ['beam', 'continuum']")
    if t_end is not None:
        config = copy.deepcopy(config)
        config["fe"]["scenes"][name] = {**config["fe"]["scenes"][name]}
        solver = dict(config["fe"]["scenes"][name].get("solver") or {})
        config["fe"]["scenes"][name]["solver"] = {**solver, "t_end": t_end}
        config.setdefault("fe", {})["control_readings_t_end"] = t_end  # the window of every reading
    _validated(config)
    cfg = effective_fe_config(config)
    readings = list(cfg.get("readings") or {})
    reading = reading or (readings[0] if readings else None)
    try:
        mapping = scene_mapping(cfg, name, reading)
    except ValueError as exc:
        raise ConfigError(f"fe.{exc}") from None
    table = Path(friction_table or project_root(root) / cfg["friction_table"])
    if not table.is_file():
        raise FileNotFoundError(
            f"fe.friction_table: {table} does not exist; build it first: "
            f"`.venv/bin/snakemake -j2 {paths.friction_table()}`"
        )
    friction = FrictionTable.from_csv(table)
    if model == "continuum":
        nx, ny = cfg["comparison"]["mesh"]
        ds = continuum_dataset(mapping, friction, nx=nx, ny=ny, name=name)
        attrs = {"scene": mapping, "interpretation": INTERPRETATION, "method": {"mesh": [nx, ny]}}
        return _finish(ds, attrs, output)
    counter = iter(range(1, 1_000))

    def build(mp):
        label = f"{name} run {next(counter)}"
        return scene_dataset(mp, friction, name, progress=progress(label) if progress else None)

    spec = None
    if ensemble:
        spec = EnsembleSpec.from_mapping(config.get("ensemble")).without_blas()
        spec = replace(spec, step_factor=HALF_STEP)
    # signs drawn by name: the scene's dataset path as rule fe_reading writes it
    ds = ensemble_dataset(
        build, mapping, spec, run_id=paths.fe_scene(reading, name), fields=PERTURBED_FIELDS
    )
    if ensemble:
        ds = apply_step_halving(ds, step_member_values(ds))
    ds.attrs["fe_reading"] = reading
    attrs = {"scene": mapping, "interpretation": INTERPRETATION, "method": {"fe_reading": reading}}
    return _finish(ds, attrs, output)
