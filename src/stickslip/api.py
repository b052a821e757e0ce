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

Your own law as a Python function of the relative speed |v_r| [mm/s] (optionally ``law_derivative``), checked
as the built-in laws are and solved by the same switch solver:

>>> ds = stickslip.simulate(law=lambda v: 0.5 / (1 + 0.5 * v), t_end=20.0, transient=5.0)
>>> ds.attrs["status"], ds.attrs["method_name"], ds.attrs["scene_friction_law"][:27]
('success', 'switch', 'CallableLaw(mu=<lambda>, st')

As ``solve_ivp`` reports, every run says what it did: ``status`` (success, diverged, failed), ``success`` and
``message``; a divergence is the model's answer, with its mechanism (the ``outcome`` variable says the same):

>>> ds = stickslip.simulate(mu_s=0.8)
>>> ds.attrs["status"], ds.attrs["success"], str(ds.outcome.attrs["flag_meanings"].split()[int(ds.outcome)])
('diverged', 1, 'diverged')
>>> print(ds.attrs["message"])  # doctest: +ELLIPSIS
diverged: slip damping C - mu_s N sigma = 1.5 - 4 = -2.5 N s/mm < 0 ...: the motion grows without bound

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
from typing import TYPE_CHECKING

import xarray as xr

if TYPE_CHECKING:  # annotations only: pydantic and the studies are imported when a function runs
    from .schema import Onedof, OnedofProject
    from .studies.specs import RunSpec

#: The name of the scene a call with changes runs (``onedof.scenes.custom``, ``fe.scenes.custom``).
CUSTOM = "custom"


def _is_project(folder: Path) -> bool:
    return (folder / "config" / "config.yaml").is_file()


def project_root(root: str | Path | None = None) -> Path:
    """The project folder: ``root``, else the checkout this package belongs to (an editable install, the
    way ``make setup`` installs it), else the working directory if it holds ``config/config.yaml``. Every
    project path (config, claims, friction table, results) is read from there, wherever the call runs."""
    from .pipeline.config import ConfigError

    if root is not None:
        folder = Path(root).expanduser()
        if not _is_project(folder):
            what = "does not exist" if not folder.exists() else "holds no config/config.yaml"
            raise ConfigError(f"root: {str(folder)!r} is not a stickslip project folder: it {what}")
        return folder.resolve()
    for candidate in (Path(__file__).resolve().parents[2], Path.cwd()):
        if _is_project(candidate):
            return candidate
    raise ConfigError(
        "root: no project folder: this package is not installed from a stickslip checkout and the working "
        "directory holds no config/config.yaml; pass root= (--root) naming the checkout"
    )


def check_output(
    output: str | Path | None, *, force: bool = False, key: str = "output", config=None
) -> Path | None:
    """``output`` as a path this call may write, checked before any work.

    Refused: a path the pipeline's catalogue names (``stickslip.catalogue``) or anything under a project's
    results folder, this project's or another checkout's (the build owns those files: a custom run there
    would be read as the pipeline's; ``force`` does not change this); an existing file unless ``force``; a
    directory; a place no file can be created in (``/proc``, a read-only or missing parent). The message
    names ``key`` (``-o`` on the command line)."""
    import tempfile

    from . import catalogue as paths
    from .pipeline.config import ConfigError

    if output is None:
        return None
    path = Path(output).expanduser()
    target = path.resolve()
    results = next((f for f in target.parents if f.name == paths.RESULTS and _is_project(f.parent)), None)
    if results is not None:
        rel = target.relative_to(results.parent).as_posix()
        named = (
            " (a catalogue path: the pipeline writes it)" if config and rel in paths.catalogue(config) else ""
        )
        raise ConfigError(
            f"{key}: {str(path)!r} is inside the pipeline's results folder {str(results)!r}{named}; the "
            "build owns every file there and would read a custom run as its own: write elsewhere (--force "
            "does not change this)"
        )
    if target.is_dir():
        raise ConfigError(f"{key}: {str(path)!r} is a directory; name a file, e.g. {str(path / 'run.nc')!r}")
    if target.exists() and not force:
        raise ConfigError(f"{key}: {str(path)!r} exists; pass --force (force=True) to overwrite it")
    parent = target.parent
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    if not parent.is_dir():
        raise ConfigError(f"{key}: {str(path)!r} cannot be written: {str(parent)!r} is not a directory")
    try:  # the real test (root may write where permission bits say no; /proc refuses new files)
        tempfile.TemporaryFile(dir=parent).close()
        if target.exists():
            open(target, "ab").close()
    except OSError as exc:
        raise ConfigError(f"{key}: {str(path)!r} cannot be written ({exc.strerror or exc})") from None
    return path


def load_project_config(configfiles: Sequence[str | Path] = (), root: str | Path | None = None) -> dict:
    """The config the Snakefile builds: every ``config/*.yaml`` of the project, then ``configfiles`` in
    order (a null removes an entry). Not yet validated.

    Built in the Snakefile's order, key order included: Snakemake reads the ``--configfile`` files first,
    then the Snakefile merges everything over them, so an overlay's keys come first in every mapping (the
    perturbation ensemble does not depend on it: its signs are drawn by run id and field path)."""
    from .pipeline.config import load_config, merge

    base = project_root(root)
    overlays = [Path(p) for p in configfiles]
    config = merge(load_config(overlays), load_config(sorted((base / "config").glob("*.yaml")) + overlays))
    inverse = config.get("inverse") or {}
    if "claims_glob" in inverse and not Path(inverse["claims_glob"]).is_absolute():
        # a path of the project, wherever the command runs: the pipeline runs in the project folder
        config["inverse"] = {**inverse, "claims_glob": str(base.resolve() / inverse["claims_glob"])}
    return config


def onedof_project(config: Mapping) -> OnedofProject:
    """The sections a 1-DOF run reads, typed (``stickslip.schema.OnedofProject``): ``ConfigError`` naming the
    key of every bad value."""
    from .schema import OnedofProject

    return _typed(OnedofProject, config)


def _typed(model, mapping: Mapping, key: str = ""):
    """``model`` of ``mapping``, else a ``ConfigError`` naming each bad value's key (under ``key``)."""
    from pydantic import ValidationError

    from .io.typed_errors import typed_errors
    from .pipeline.config import ConfigError

    try:
        return model.model_validate(mapping)
    except ValidationError as exc:
        raise ConfigError("\n".join(f"{key}{line}" for line in typed_errors(exc).splitlines())) from None


#: Relative speeds [mm/s] a law given as an object or a callable is checked at (and fingerprinted by):
#: 0, then 1e-6 to 1e3 mm/s geometrically, far beyond any speed a 1-DOF run of the paper reaches.
LAW_CHECK_SPEEDS = (0.0, *(10.0 ** (k / 4.0) for k in range(-24, 13)))


def _callable_law_class():
    """``CallableLaw``, defined on first use (``import stickslip.api`` stays free of numpy)."""
    import hashlib

    import numpy as np

    from .model.laws import FrictionLaw

    class CallableLaw(FrictionLaw):
        """A friction law from a Python callable: ``mu(v_r)`` [1] of the relative speed |v_r| >= 0 [mm/s],
        optionally its derivative ``dmu(v_r)`` [s/mm] and the static limit (default mu(0)). Solved by the
        switch solver like the built-in laws; below 0 (the continuation a high-order step across v_r = 0
        may ask for) the law is continued linearly with its slope at 0 (``dmu(0)``, else a difference
        quotient). ``repr`` carries a digest of the values at ``LAW_CHECK_SPEEDS``, so two different
        callables never share a record or a kept solve."""

        kind = "callable"

        def __init__(self, mu, dmu=None, static=None, name: str = "", continued=False, breakpoints=()):
            self._mu, self._continued, self._breakpoints = mu, continued, tuple(breakpoints)
            self.name = name or getattr(mu, "__name__", None) or type(mu).__name__
            self._static = float(mu(0.0)) if static is None else float(static)
            h = 1e-7
            self._slope0 = float(dmu(0.0)) if dmu is not None else (float(mu(h)) - float(mu(0.0))) / h
            values = [float(mu(v)) for v in LAW_CHECK_SPEEDS]
            code = getattr(mu, "__code__", None)  # a function's code as well as its values: two that
            body = (code.co_code, repr(code.co_consts)) if code is not None else ()  # differ between them
            record = repr((values, self._static, self._slope0, body)).encode()
            self._digest = hashlib.sha256(record).hexdigest()[:12]

        @property
        def static(self) -> float:
            return self._static

        @property
        def breakpoints(self) -> tuple[float, ...]:
            return self._breakpoints

        def _scalar(self, speed: float) -> float:
            if speed >= 0.0 or self._continued:
                return float(self._mu(speed))
            return float(self._mu(0.0)) + self._slope0 * speed

        def mu_continued(self, speed):
            if isinstance(speed, float):
                return self._scalar(speed)
            arr = np.asarray(speed, dtype=float)
            return np.vectorize(self._scalar, otypes=[float])(arr) if arr.ndim else self._scalar(float(arr))

        def describe(self) -> dict:
            return {"kind": self.kind, "mu": self.name, "static": self._static, "digest": self._digest}

        def __repr__(self) -> str:
            return f"CallableLaw(mu={self.name}, static={self._static!r}, digest={self._digest})"

    return CallableLaw


def own_law(law, law_derivative: Callable[[float], float] | None = None, key: str = "law"):
    """A law given as an object, as a checked ``CallableLaw``; None for a config mapping or a built-in law
    (those go through the config, as the pipeline's).

    ``law``: a Python callable ``mu(v_r)`` of the relative speed [mm/s] (``law_derivative`` its derivative
    [s/mm], checked against mu's difference quotients, or the pair ``(mu, dmu)`` as ``law``; the static
    limit is mu(0)), or a ``FrictionLaw`` the config cannot name: your own subclass or a table in memory,
    with its formula (continued below 0 as it defines), static limit and breakpoints, recorded by name and a
    digest of its values (two tables in memory share a repr, and a kept solve is found by it). The checks
    every built-in law makes: mu finite and >= 0 at every speed of ``LAW_CHECK_SPEEDS``, the static limit
    finite and > 0, and mu(0+) not above it (a mass released from stick would be pushed back into it).
    Errors name ``key``."""
    import math

    from .model.laws import LAW_KINDS, FrictionLaw
    from .pipeline.config import ConfigError

    if isinstance(law, tuple) and len(law) == 2 and all(map(callable, law)) and law_derivative is None:
        law, law_derivative = law
    if law is None or (isinstance(law, Mapping) and law_derivative is None):
        return None
    is_law = isinstance(law, FrictionLaw)
    if law_derivative is None and is_law and type(law) is LAW_KINDS.get(law.kind) and law.kind != "tabulated":
        return None  # a built-in law: its config mapping, checked by the config layer
    derivative_ok = law_derivative is None or (callable(law_derivative) and not is_law)
    if not (is_law or callable(law)) or not derivative_ok:
        raise ConfigError(
            f"{key}: expected a config mapping ({{'kind': 'stribeck', ...}}), a FrictionLaw or a callable "
            f"mu(v_r), got {type(law).__name__}"
            + ("" if law_derivative is None else " (law_derivative: a callable dmu(v_r) of a callable law)")
        )
    try:  # the user's code: its own error, named
        if is_law:
            source = getattr(law, "source", "")
            name = f"{type(law).__name__}({source})" if source else type(law).__name__
            settings = dict(static=law.static, name=name, continued=True, breakpoints=law.breakpoints)
            made = _callable_law_class()(law.mu_continued, **settings)
        else:
            made = _callable_law_class()(law, law_derivative)
        static = float(made.static)
        values = [float(made.mu_continued(v)) for v in LAW_CHECK_SPEEDS]
        zero_plus = max(values[0], float(made.mu_continued(1e-12)))  # a jump right after 0 too
    except Exception as exc:
        raise ConfigError(f"{key}: evaluating the law failed: {type(exc).__name__}: {exc}") from None
    if not (math.isfinite(static) and static > 0):
        raise ConfigError(f"{key}: the static limit must be finite and > 0, got {static!r}")
    for v, mu in zip(LAW_CHECK_SPEEDS, values, strict=True):
        if not (math.isfinite(mu) and mu >= 0):
            raise ConfigError(
                f"{key}: mu({v:g} mm/s) = {mu!r}; mu must be finite and >= 0 (a magnitude |F|/N)"
            )
    if zero_plus > static * (1 + 1e-9):
        raise ConfigError(f"{key}: mu(0+) = {zero_plus!r} exceeds the static limit {static!r}")
    for v in LAW_CHECK_SPEEDS[1:] if law_derivative is not None else ():
        h = 1e-6 * v
        quotient = (float(law(v + h)) - float(law(v - h))) / (2 * h)
        given = float(law_derivative(v))
        scale = max(abs(quotient), abs(float(law(v))) / max(v, 1e-300) * 1e-6, 1e-9)
        if not math.isfinite(given) or abs(given - quotient) > 1e-3 * scale + 1e-6:
            raise ConfigError(
                f"{key} derivative: dmu({v:g} mm/s) = {given!r} but mu's difference quotient there is "
                f"{quotient:.6g}: not mu's derivative"
            )
    return made


def onedof_scenario(
    onedof: Onedof,
    scene: str | None = None,
    *,
    law=None,
    run: Mapping | None = None,
    params: Mapping | None = None,
) -> tuple[Onedof, str]:
    """(section, scene name) with the changes as a scene of their own: ``onedof.scenes.custom`` = ``scene``
    (default: the baseline's) with ``params``, ``law`` (a config mapping or a built-in law; a law without
    ``mu_s`` takes the run's) and ``run`` lengths over it, checked as a config scene is; a law of
    ``own_law`` is only named in the description (not a config value: the run replaces its spec's law).
    Without changes the scene itself, so the run is the pipeline's run of that scene."""
    from .schema import Scene

    scene = scene or onedof.baseline.scene
    _refs(("scene", scene), onedof.scenes, "onedof.scenes")
    params, run = dict(params or {}), dict(run or {})
    if not (params or run or law is not None):
        return onedof, scene
    base = onedof.scenes[scene].model_dump(exclude_unset=True)
    changes = ", ".join(f"{k}={v}" for k, v in {**params, **run}.items())
    entry = {
        **base,
        "figure": "",
        "description": f"scene {scene} with {changes or 'its own friction law'}",
        "params": {**base.get("params", {}), **params},
        **run,
    }
    if getattr(law, "kind", None) == "callable":
        entry["description"] += f", friction law {law!r}"
    elif law is not None:
        entry["law"] = dict(law.describe()) if hasattr(law, "describe") else dict(law)
        if entry["law"].get("kind") not in ("tabulated", None):  # every law but a table has a mu_s
            entry["law"].setdefault("mu_s", entry["params"].get("mu_s", onedof.defaults.params.mu_s))
        entry["description"] += f", friction law {entry['law']['kind']}"
    custom = _typed(Scene, entry, f"onedof.scenes.{CUSTOM}.")
    return onedof.model_copy(update={"scenes": {**onedof.scenes, CUSTOM: custom}}), CUSTOM


def _refs(ref: tuple[str, str], known: Mapping, section: str) -> None:
    """``schema.base.check_refs`` of one (key, name), as a ``ConfigError``."""
    from .pipeline.config import ConfigError
    from .schema import check_refs

    try:
        check_refs([ref], known, section)
    except ValueError as exc:
        raise ConfigError(str(exc)) from None


def simulate(
    scene: str | None = None,
    *,
    reading: str | None = None,
    method: str | None = None,
    law=None,
    law_derivative: Callable[[float], float] | None = None,
    t_end: float | None = None,
    output_dt: float | None = None,
    transient: float | None = None,
    count_window: float | None = None,
    ensemble: bool = False,
    output: str | Path | None = None,
    force: bool = False,
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
    the model's answer, not an error. The variable ``outcome`` (flags ``stick_slip no_stick rest diverged
    failed``, attribute ``mechanism``) says the same per run. Every metric is there, NaN where the run
    defines none.

    ``scene``, ``reading`` and ``method`` are entries of ``onedof.scenes/readings/methods`` (default: the
    baseline's, ``onedof.baseline``; with a ``law`` the default method is ``switch``). ``params`` are the
    scene's parameters (``mass``, ``stiffness``, ``damping``, ``mu_s``, ``sigma``, ``normal_force``, ``x0``,
    ``v0``, ``belt_velocity``, ``belt_deceleration``, ``units``, ``plateau_speed``).

    ``law`` replaces the reading's friction (switch solver): a config mapping (``{"kind": "stribeck",
    "mu_k": 0.3, "v_s": 0.5}``; ``mu_s`` defaults to the run's; ``stickslip laws`` lists the kinds), a law of
    ``stickslip.model.laws`` or your own ``FrictionLaw`` subclass, or a Python callable ``mu(v_r)`` of the
    relative speed |v_r| >= 0 [mm/s] (``law_derivative``: its derivative [s/mm], checked against mu's
    difference quotients; the static limit is mu(0)). Every law passes the built-in laws' checks before the
    run: mu finite and >= 0 from 0 to 1000 mm/s, mu(0+) not above the static limit.

    ``ensemble`` adds the config's perturbation ensemble (``<metric>_ensemble``), built over this run's
    config.
    ``output`` writes the dataset with the pipeline's writer and returns it as read back (checksum verified);
    it is checked before any work: never a path of the pipeline's results folder, never an existing file
    unless ``force``, never a directory or a place no file can be created. ``config``: the project config
    already loaded (``load_project_config``) instead of reading ``configfiles``. The run's size is bounded
    by the pipeline's cost guard (``stickslip.schema``: samples per run, and samples of the
    ensemble's runs together), checked before any work unless the config says ``allow_expensive: true``.
    A bad value raises ``ConfigError`` naming its key."""
    from dataclasses import replace

    from .catalogue import onedof_dataset
    from .ensemble import EnsembleSpec, ensemble_dataset
    from .pipeline.config import ConfigError
    from .schema import OnedofJob, OnedofRuns, check_run_lengths, given, scene_run_lengths
    from .studies.onedof import scene_run_dataset
    from .studies.specs import PERTURBED_FIELDS, from_job_params, run_spec

    base_root = project_root(root)
    config = config if config is not None else load_project_config(configfiles, base_root)
    output = check_output(output, force=force, config=config)
    project = onedof_project(config)
    lengths = dict(t_end=t_end, output_dt=output_dt, transient=transient, count_window=count_window)
    run = {k: v for k, v in lengths.items() if v is not None}  # the scene's run lengths you set
    own = own_law(law, law_derivative, f"onedof.scenes.{CUSTOM}.law")
    onedof, name = onedof_scenario(
        project.onedof, scene, law=law if own is None else own, run=run, params=params
    )
    reading = reading or onedof.baseline.reading
    method = method or ("switch" if law is not None else onedof.baseline.method)
    _refs(("reading", reading), onedof.readings, "onedof.readings")
    _refs(("method", method), onedof.methods, "onedof.methods")
    if own is not None and onedof.methods[method].solver != "switch":
        raise ConfigError(
            f"onedof.scenes.{name}.law: a {own.kind!r} friction law is solved by the 'switch' solver "
            f"only; method {method!r} uses {onedof.methods[method].solver!r}"
        )

    def spec_of(section):
        spec = run_spec(section, name, reading, method)
        return spec if own is None else replace(spec, law=own)

    # the params of the pipeline's job for this run (onedof_subconfig): what its ensemble perturbs
    chosen = {"readings": reading, "methods": method, "scenes": name}
    runs = {key: {n: getattr(onedof, key)[n]} for key, n in chosen.items()}
    job = OnedofJob(onedof=OnedofRuns(baseline=onedof.baseline, defaults=onedof.defaults, **runs))
    try:
        check_run_lengths(*scene_run_lengths(onedof, name, reading))
        spec = spec_of(job.onedof)
    except ValueError as exc:
        raise ConfigError(str(exc)) from None
    members = EnsembleSpec.from_mapping(given(project.ensemble)).without_blas() if ensemble else None
    check_run_cost(spec, members, given=run, allow_expensive=project.allow_expensive)
    ds = ensemble_dataset(  # signs drawn by name: the run's dataset path in the pipeline's catalogue
        from_job_params(lambda section: scene_run_dataset(spec_of(section))),
        job.model_dump(exclude_unset=True),
        members,
        run_id=onedof_dataset(name, reading, method),
        fields=PERTURBED_FIELDS,
    )
    attrs = {
        "scene": spec.scene_attrs(),
        "interpretation": spec.interpretation(),
        "method": {"name": method, **spec.solver_settings, **ds.attrs.pop("solver_run_settings", {})},
        "title": f"{spec.figure} {name}: reading {reading}, method {method}".strip(),
    }
    return _finish(ds, attrs, output)


def check_run_cost(
    spec: RunSpec, ensemble_spec=None, given: Mapping = (), allow_expensive: bool = False
) -> None:
    """The pipeline's cost guard (``stickslip.schema``) for one run, before any work: its samples
    (``stored_samples``) against ``MAX_SAMPLES_PER_RUN``, then the ensemble's (``check_ensemble_cost``).
    Skipped with ``allow_expensive: true`` in the config, as in the pipeline. The message names the key
    (the option ``given`` set), the cost and the bound."""
    from .pipeline.config import ConfigError
    from .schema import MAX_SAMPLES_PER_RUN, stored_samples

    if allow_expensive:
        return
    estimate = stored_samples(spec.t_end, spec.output_dt)
    option = "output_dt" if "output_dt" in given and "t_end" not in given else "t_end"
    if estimate > MAX_SAMPLES_PER_RUN:
        raise ConfigError(
            f"onedof.scenes.{spec.scene}.{option}: {dict(given).get(option, '')!r} (t_end = "
            f"{spec.t_end:g} s at output_dt = {spec.output_dt:g} s) makes an estimated {estimate:.3g} "
            f"samples per run, more than the limit {MAX_SAMPLES_PER_RUN:.3g} (the pipeline's cost guard); a "
            "shorter t_end or a coarser output_dt fits, or allow_expensive: true in a config file"
        )
    check_ensemble_cost(ensemble_spec, estimate)


def check_ensemble_cost(spec, samples_per_run: float, *, allow_expensive: bool = False) -> None:
    """The pipeline's bounds on an ensemble, before any work: at most ``MAX_ENSEMBLE_SEEDS`` seeds, and its
    runs together (the base run, one per seed, the step member, the window and BLAS members) at most
    ``MAX_SAMPLES_PER_STUDY`` samples. Skipped with ``allow_expensive: true``. The message names the key
    (``ensemble.seeds``), the cost and the bound."""
    from .pipeline.config import ConfigError
    from .schema import MAX_ENSEMBLE_SEEDS, MAX_SAMPLES_PER_STUDY

    if spec is None or allow_expensive:
        return
    seeds = len(spec.seeds)
    members = 2 + seeds + (spec.window_factor is not None) + (spec.blas_threads is not None)
    if seeds > MAX_ENSEMBLE_SEEDS:
        raise ConfigError(
            f"ensemble.seeds: {seeds} seeds make {members} runs of this one, more than the limit "
            f"{MAX_ENSEMBLE_SEEDS} seeds (the pipeline's cost guard); fewer seeds, or allow_expensive: true"
        )
    if members * samples_per_run > MAX_SAMPLES_PER_STUDY:
        raise ConfigError(
            f"ensemble.seeds: {seeds} seeds make {members} runs of {samples_per_run:.3g} samples, "
            f"an estimated {members * samples_per_run:.3g} samples, more than the limit "
            f"{MAX_SAMPLES_PER_STUDY:.3g} (the pipeline's cost guard for a study); fewer seeds, or "
            "allow_expensive: true"
        )


def _finish(ds: xr.Dataset, attrs: dict, output) -> xr.Dataset:
    """Write with the pipeline's writer and read back, or attach the same provenance in memory."""
    from .io.netcdf import provenance_attrs, read_dataset, write_dataset

    if output is not None:
        write_dataset(ds, output, **attrs)
        return read_dataset(output)
    title = attrs.pop("title", None) or ds.attrs.get("title", "")
    ds.attrs = {**provenance_attrs(title=title, **attrs), **ds.attrs}
    return ds


def _stem(scene: str) -> str:
    return scene.rsplit("_", 2)[0] if scene.endswith("mm_s") else scene.rsplit("_", 1)[0]


def fe_scene_name(
    scenes: Mapping[str, Mapping], scene: str, speed: float | None = None, rpm: float | None = None
) -> tuple[str, dict | None]:
    """(name, entry) of the scene to run: a scene of ``scenes`` (``fe.scenes`` as given) by its name, or by
    its stem and a disc speed, ``speed`` (surface speed [mm/s]) or ``rpm`` [rev/min]. A configured speed
    is that scene (``section9_kinematic`` with speed 0.5 is ``section9_kinematic_0p5mm_s``, entry None); any
    other speed is a new scene (entry: the stem's scene with its disc speed replaced), named as the config
    names them (``section9_kinematic_2mm_s``, ``section9_kinematic_30rpm``)."""
    import math

    from .pipeline.config import ConfigError

    given = [(k, v) for k, v in (("speed", speed), ("rpm", rpm)) if v is not None]
    if len(given) > 1:
        raise ConfigError("speed: give --speed (mm/s) or --rpm (rev/min), not both")
    for key, value in given:
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if not number or not math.isfinite(value) or value <= 0:
            what = "surface speed [mm/s]" if key == "speed" else "disc speed [rev/min]"
            raise ConfigError(f"{key}: the {what} must be a finite number > 0, got {value!r}")
    if scene in scenes and not given:
        return scene, None
    stem = scene if scene not in scenes else _stem(scene)
    family = sorted(s for s in scenes if _stem(s) == stem)
    if not family:
        raise ConfigError(
            f"fe.scenes.{scene}: no such scene (scenes: {sorted(scenes)}; or a stem "
            f"{sorted({_stem(s) for s in scenes})} with --speed MM_S or --rpm N for any disc speed)"
        )
    if not given:
        raise ConfigError(
            f"fe.scenes.{scene}: a stem, not a scene: add --speed MM_S or --rpm N (configured: {family})"
        )
    key, value = given[0]
    disc_key, unit = ("surface_speed_mm_s", "mm_s") if key == "speed" else ("speed_rev_per_min", "rpm")
    name = f"{stem}_{value:g}{unit}".replace(".", "p").replace("+", "")
    if name in scenes:
        return name, None
    base = next((s for s in family if disc_key in ((scenes[s] or {}).get("disc") or {})), family[0])
    entry = copy.deepcopy(scenes[base] or {})
    speeds = ("speed_rev_per_min", "surface_speed_mm_s")
    disc = {k: v for k, v in (entry.get("disc") or {}).items() if k not in speeds}
    entry["disc"] = {**disc, disc_key: float(value)}
    return name, entry


def simulate_fe(
    scene: str,
    *,
    speed: float | None = None,
    rpm: float | None = None,
    reading: str | None = None,
    model: str = "beam",
    t_end: float | None = None,
    ensemble: bool = True,
    progress: Callable[[str], Callable[[int, int], None]] | None = None,
    output: str | Path | None = None,
    force: bool = False,
    friction_table: str | Path | None = None,
    configfiles: Sequence[str | Path] = (),
    root: str | Path | None = None,
) -> xr.Dataset:
    """One beam-on-disc scene (``fe.scenes``) under one FE reading (default: the first, the paper's
    geometry reading), as rule ``fe_reading`` computes it: with ``model="beam"`` and ``ensemble`` the
    perturbation ensemble and the step-halving check, so ``output`` equals the pipeline's
    ``results/fe/<reading>/<scene>.nc`` for the same config. ``model="continuum"`` runs the continuum strip
    of the model comparison (``fe.comparison.mesh``) on the scene instead.

    ``scene`` is a scene name, or a stem (``section9_kinematic``) with a disc speed: ``speed`` the surface
    speed [mm/s] or ``rpm`` the disc's rev/min, any value > 0 (a speed the config has is its scene; any
    other runs the stem's scene at that speed, ``section9_kinematic_2mm_s``). ``t_end`` [s] overrides the
    scene's window; ``progress(label)`` returns a ``(done, total)`` callback per run (time steps). The
    friction law is the Fig. 17 table (``fe.friction_table``, written by rule friction_table; computed as
    that rule computes it when no build has written it yet). ``output`` is checked before any work as in
    ``simulate``; the pipeline's cost guard bounds the run (samples, element-increments) and the ensemble."""
    from dataclasses import replace

    from . import catalogue as paths
    from .ensemble import EnsembleSpec, ensemble_dataset, step_member_values
    from .fe.params import SolverParams
    from .fe.quantities import INTERPRETATION
    from .fe.step_halving import HALF_STEP, apply_step_halving
    from .pipeline.config import ConfigError, merge, validate_config
    from .schema import given
    from .studies.fe_config import PERTURBED_FIELDS, effective_fe, scene_mapping
    from .studies.fe_continuum import continuum_dataset
    from .studies.fe_scene import scene_dataset

    base_root = project_root(root)
    config = load_project_config(configfiles, base_root)
    output = check_output(output, force=force, config=config)
    if model not in ("beam", "continuum"):
        raise ConfigError(f"model: {model!r} is not one of ['beam', 'continuum']")
    try:  # your t_end's own key, checked by the config's bound
        SolverParams(t_end=1.0 if t_end is None else t_end)
    except ValueError as exc:
        raise ConfigError(f"{exc} (the simulated window [s])") from None
    # the config as given (not yet validated): your scene and window go on top of it, as a config file would
    name, entry = fe_scene_name(config["fe"]["scenes"], scene, speed, rpm)
    yours: dict = {"scenes": {name: entry}} if entry is not None else {}
    if t_end is not None:  # the window of your scene under every reading
        window = {"scenes": {name: {"solver": {"t_end": t_end}}}, "control_readings_t_end": t_end}
        yours = merge(yours, window)
    config = merge(config, {"fe": yours})
    try:  # the whole config checked as the Snakefile checks it (your window and scene, readings, cost)
        typed = validate_config(config, producible=[paths.friction_table()])
    except ConfigError as exc:
        costly = ("samples over solver.t_end", "element-increments")
        if t_end is not None and any(c in str(exc) for c in costly):  # the guard met your window
            raise ConfigError(f"t_end: {t_end!r} s is beyond the pipeline's cost guard: {exc}") from None
        raise
    fe = effective_fe(typed)
    reading = reading or next(iter(fe.readings))
    try:
        mapping = scene_mapping(fe, name, reading)
    except ValueError as exc:
        raise ConfigError(f"fe.{exc}") from None
    spec = None
    if ensemble and model == "beam":
        spec = replace(EnsembleSpec.from_mapping(given(typed.ensemble)).without_blas(), step_factor=HALF_STEP)
        solver = SolverParams.from_mapping(mapping["solver"])  # samples per run: t_end / output_dt
        check_ensemble_cost(spec, solver.t_end / solver.output_dt + 1, allow_expensive=typed.allow_expensive)
    friction = _fe_friction_table(config, fe.friction_table, base_root, friction_table)
    if model == "continuum":
        nx, ny = fe.comparison.mesh
        ds = continuum_dataset(mapping, friction, nx=nx, ny=ny, name=name)
        attrs = {"scene": mapping, "interpretation": INTERPRETATION, "method": {"mesh": [nx, ny]}}
        return _finish(ds, attrs, output)
    counter = iter(range(1, 1_000))

    def build(mp):
        label = f"{name} run {next(counter)}"
        return scene_dataset(mp, friction, name, progress=progress(label) if progress else None)

    # signs drawn by name: the scene's dataset path as rule fe_reading writes it
    ds = ensemble_dataset(build, mapping, spec, run_id=paths.fe_scene(reading, name), fields=PERTURBED_FIELDS)
    if ensemble:
        ds = apply_step_halving(ds, step_member_values(ds))
    ds.attrs["fe_reading"] = reading
    attrs = {"scene": mapping, "interpretation": INTERPRETATION, "method": {"fe_reading": reading}}
    return _finish(ds, attrs, output)


def _fe_friction_table(config: dict, configured: str, root: Path, given):
    """The FE friction law: ``given``, else ``configured`` (the project's ``fe.friction_table``); the
    pipeline's own table (rule friction_table's output) computed here as that rule computes it when no build
    has written it."""
    import io

    from . import catalogue as paths
    from .fe.params import FrictionTable

    table = Path(given) if given is not None else root / configured
    if table.is_file():
        return FrictionTable.from_csv(table)
    if given is not None or configured != paths.friction_table():
        raise FileNotFoundError(f"fe.friction_table: {table} does not exist")
    from .studies.onedof import friction_table_from_config

    ds = friction_table_from_config(onedof_project(config).onedof)
    rows = zip(ds.relative_speed.values, ds.mu.values, strict=True)  # the rule's CSV, so the rule's values
    csv = "relative_velocity_mm_per_s,mu\n" + "".join(f"{v:.10g},{m:.10g}\n" for v, m in rows)
    return FrictionTable.from_csv(io.StringIO(csv))
