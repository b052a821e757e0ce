"""Perturbation ensembles: how much each measured number moves under changes that must not matter.

A dataset is built by a pure function of its config mapping. The ensemble calls that function on the base
mapping and on perturbed copies of it:

* ``perturbed-<seed>``: every field the run declares physical or numerical (``fields``: parameters, initial
  state, solver settings; never output windows, sample spacings or counts) multiplied by (1 + s * relative).
  The sign s = +-1 of each field is a hash of (seed, run id, the field's path) alone (``draw_sign``): it does
  not depend on the order of the keys, on any other key of the mapping, or on ``1`` being written for
  ``1.0``, so such an edit leaves every other run's members as they were;
* ``step``: the step-controlling settings named in ``step_keys`` (tolerances, fixed steps, safety factors)
  multiplied by ``step_factor`` - a second time step for the time-stepping methods; left out when the
  mapping has none of them (the exact solver has no step), so it never duplicates the base run;
* ``window``: the measurement window's start (``window_keys``: the 1-DOF ``transient``) times
  ``window_factor``, the same run measured over a later, shorter steady window. On a limit cycle every metric
  stays put; on a run that decays to rest the amplitudes are what is left of a transient where the window
  begins, and this member moves them by orders of magnitude: such numbers are never ordered (a window is a
  measuring choice, and a result must not depend on it). Left out when the mapping has no window start;
* ``blas-threads-<n>``: the base mapping run with the BLAS limited to ``n`` threads (a different summation
  order in every BLAS call).

Every data variable on no time axis (the metrics) gets a companion ``<name>_ensemble`` with a
leading ``ensemble_member`` dimension holding the value of every member (the base run first). The claims
table takes its ``spread`` from these: a claim whose margin to its threshold is within 3 spreads is
``indistinguishable`` - never reproduced or deviating by luck.
"""

from __future__ import annotations

import copy
import hashlib
from collections.abc import Callable, Collection, Mapping
from contextlib import nullcontext
from dataclasses import replace
from fnmatch import fnmatchcase
from typing import TYPE_CHECKING, Annotated

import numpy as np
from pydantic import Field
from pydantic.dataclasses import dataclass

if TYPE_CHECKING:  # the config check reads EnsembleSpec at parse time: no xarray there (0.5 s a no-op)
    import xarray as xr

MEMBER_DIM = "ensemble_member"
SUFFIX = "_ensemble"

#: Settings that control a time step or an error tolerance (1-DOF methods and the FE solvers).
DEFAULT_STEP_KEYS = ("rtol", "atol", "h", "max_step", "safety_factor", "eta", "first_step")
#: Settings where a run's measurement window starts (the 1-DOF steady window; the FE scenes have none).
DEFAULT_WINDOW_KEYS = ("transient",)


@dataclass(frozen=True)
class EnsembleSpec:
    """What the ensemble perturbs (the ``ensemble`` config section's bounds, checked at construction: a
    pydantic ``ValidationError``, a ``ValueError``, names the field)."""

    relative: Annotated[float, Field(gt=0, lt=1e-3, allow_inf_nan=False)] = 1e-12
    seeds: tuple[int, ...] = (1, 2)
    step_factor: Annotated[float, Field(gt=0, lt=1, allow_inf_nan=False)] = 0.5
    step_keys: tuple[str, ...] = DEFAULT_STEP_KEYS
    blas_threads: Annotated[int, Field(ge=1)] | None = 1
    window_factor: Annotated[float, Field(gt=1, le=2, allow_inf_nan=False)] | None = None
    window_keys: tuple[str, ...] = DEFAULT_WINDOW_KEYS

    def without_blas(self) -> EnsembleSpec:
        """For computations that make no BLAS calls (the 1-DOF solvers: a test shows their output
        bit-identical under any BLAS thread count), where that member would only repeat the base run."""
        return replace(self, blas_threads=None)

    @classmethod
    def from_mapping(cls, data: Mapping | None) -> EnsembleSpec:
        """From the ``ensemble`` config section (its keys and types checked by the typed config layer)."""
        return cls(**{k: v for k, v in (data or {}).items() if v is not None})


def draw_sign(seed: int, run_id: str, field: str) -> float:
    """The sign (+1.0 or -1.0) of one field's perturbation: the first bit of sha256 over (seed, run id,
    field path) only. Independent of everything else in the mapping and of the machine."""
    digest = hashlib.sha256(f"{int(seed)}\x1f{run_id}\x1f{field}".encode()).digest()
    return 1.0 if digest[0] & 1 else -1.0


def declared(path: str, fields: Collection[str]) -> bool:
    """Whether the value at ``path`` (dotted keys, ``[i]`` for list positions) is a declared field: a
    pattern of ``fields`` (``fnmatch``, ``*`` within or across keys) matches the path or its tail after a
    dot, so ``beam.length`` declares ``beam.length`` and ``defaults.beam.length`` alike."""
    name = ".".join(part.split("[", 1)[0] for part in path.split("."))  # ``values[2]`` is a ``values`` field
    return any(fnmatchcase(name, p) or fnmatchcase(name, "*." + p) for p in fields)


def _map_numbers(node, fn: Callable[[str, str, float], object], path: str = "", key: str = ""):
    """Copy of a nested mapping with every number (not a bool) at ``path`` replaced by ``fn(path, key,
    value)``; ``key`` is the mapping key the number (or its list) sits under."""
    if isinstance(node, Mapping):
        return {k: _map_numbers(v, fn, f"{path}.{k}" if path else str(k), str(k)) for k, v in node.items()}
    if isinstance(node, (list, tuple)):
        return [_map_numbers(v, fn, f"{path}[{i}]", key) for i, v in enumerate(node)]
    if isinstance(node, (int, float)) and not isinstance(node, bool):
        return fn(path, key, node)
    return node


def perturbed_mapping(
    mapping: Mapping, relative: float, seed: int, *, run_id: str, fields: Collection[str]
) -> dict:
    """Every declared field times (1 +- relative), the sign of each drawn by ``draw_sign(seed, run_id, its
    path)``. A declared field written as an integer is perturbed as the float it stands for."""

    def scale(path, _key, value):
        if not declared(path, fields):
            return value
        return float(value) * (1.0 + relative * draw_sign(seed, run_id, path))

    return _map_numbers(copy.deepcopy(dict(mapping)), scale)


def scaled_mapping(mapping: Mapping, factor: float, keys: tuple[str, ...]) -> dict | None:
    """The mapping with every setting named in ``keys`` times ``factor``; None when that changes nothing
    (no such setting, or only zeros)."""
    scaled = _map_numbers(
        copy.deepcopy(dict(mapping)), lambda _p, key, v: float(v) * factor if key in keys else v
    )
    return None if scaled == dict(mapping) else scaled


def members(
    mapping: Mapping,
    spec: EnsembleSpec,
    *,
    run_id: str,
    fields: Collection[str],
    blas_threads_now: int | None = None,
) -> list[tuple[str, dict, int | None]]:
    """(label, mapping, BLAS thread limit) of every member, the base run first. ``blas_threads_now``: the
    BLAS threads the base run already uses; a BLAS member limited to as many or more would repeat it."""
    out = [("base", dict(mapping), None)]
    out += [
        (f"perturbed-{s}", perturbed_mapping(mapping, spec.relative, s, run_id=run_id, fields=fields), None)
        for s in spec.seeds
    ]
    stepped = scaled_mapping(mapping, spec.step_factor, spec.step_keys)
    if stepped is not None:
        out.append(("step", stepped, None))
    windowed = scaled_mapping(mapping, spec.window_factor, spec.window_keys) if spec.window_factor else None
    if windowed is not None:
        out.append(("window", windowed, None))
    already = blas_threads_now is not None and blas_threads_now <= int(spec.blas_threads or 0)
    if spec.blas_threads is not None and not already:
        out.append((f"blas-threads-{spec.blas_threads}", dict(mapping), int(spec.blas_threads)))
    return out


def blas_threads_now() -> int | None:
    """The most threads any loaded BLAS uses now (None: no BLAS loaded)."""
    from threadpoolctl import threadpool_info

    counts = [info["num_threads"] for info in threadpool_info() if info.get("user_api") == "blas"]
    return max(counts) if counts else None


def _run(build: Callable[[dict], xr.Dataset], mapping: dict, threads: int | None) -> xr.Dataset:
    from threadpoolctl import threadpool_limits

    with nullcontext() if threads is None else threadpool_limits(limits=threads, user_api="blas"):
        return build(mapping)


def metric_names(ds: xr.Dataset) -> list[str]:
    """Data variables measured once per run: numeric, on no time axis (neither ``time`` nor a binned time
    axis such as ``bin_time``: a series is drawn, not claimed, and would multiply the file by the members)."""
    return [
        name
        for name, var in ds.data_vars.items()
        if not any("time" in str(d) for d in var.dims)
        and np.issubdtype(var.dtype, np.number)
        and not name.endswith(SUFFIX)
    ]


def step_member_values(ds: xr.Dataset) -> dict[str, np.ndarray]:
    """Every metric's value in the ``step`` member (the run at the second step size); empty when the
    ensemble has no such member. With ``step_factor`` 0.5 on a safety factor this is the step-halving run."""
    labels = ds.coords.get(f"{MEMBER_DIM}_label")
    if labels is None or "step" not in list(labels.values):
        return {}
    k = list(labels.values).index("step")
    return {
        name[: -len(SUFFIX)]: np.asarray(var.values[k], dtype=float)
        for name, var in ds.data_vars.items()
        if name.endswith(SUFFIX)
    }


def stack_members(datasets: list[xr.Dataset], labels: list[str]) -> xr.Dataset:
    """The base dataset plus ``<metric>_ensemble`` variables (member values, base first). A metric a member
    lacks (its run failed) is NaN there, so the spread becomes infinite and the claim indistinguishable."""
    base = datasets[0].copy()
    stacked = {}  # assigned at once: each single assignment re-aligns the whole dataset
    for name in metric_names(base):
        var = base[name]
        nan = np.full(var.shape, np.nan)
        values = [
            np.asarray(ds[name].values, dtype=float) if name in ds and ds[name].shape == var.shape else nan
            for ds in datasets
        ]
        attrs = {
            "units": var.attrs.get("units", "1"),
            "long_name": f"{var.attrs.get('long_name', name)}, per perturbation-ensemble member",
        }
        stacked[name + SUFFIX] = ((MEMBER_DIM, *var.dims), np.stack(values), attrs)
    base = base.assign(stacked)
    # An integer dimension coordinate and the labels as an auxiliary coordinate: CF wants dimension
    # coordinates numeric and monotonic.
    index_attrs = {"long_name": "perturbation-ensemble member index (0: the base run)", "units": "1"}
    label_attrs = {"long_name": "perturbation-ensemble member"}
    base = base.assign_coords(
        {
            MEMBER_DIM: (MEMBER_DIM, np.arange(len(labels), dtype=np.int32), index_attrs),
            f"{MEMBER_DIM}_label": (MEMBER_DIM, np.array(labels, dtype=object), label_attrs),
        }
    )
    return base


def ensemble_dataset(
    build: Callable[[dict], xr.Dataset],
    mapping: Mapping,
    spec: EnsembleSpec | None,
    *,
    run_id: str,
    fields: Collection[str],
) -> xr.Dataset:
    """``build(mapping)`` with the ensemble's member values attached (see the module docstring).

    ``run_id`` names the run (its dataset path) and ``fields`` declares which fields of ``mapping`` are
    physical or numerical (patterns, see ``declared``): together with the seed they decide every sign."""
    if spec is None:
        return build(dict(mapping))
    runs = members(mapping, spec, run_id=run_id, fields=fields, blas_threads_now=blas_threads_now())
    datasets = [_run(build, m, threads) for _, m, threads in runs]
    ds = stack_members(datasets, [label for label, _, _ in runs])
    ds.attrs["ensemble"] = (
        f"{len(runs)} members: base, every declared physical or numerical field x (1 +- {spec.relative:g}), "
        f"signs hashed from (seed, {run_id!r}, field path) for seeds {list(spec.seeds)}, "
        f"step settings {list(spec.step_keys)} x {spec.step_factor:g} where present, "
        f"BLAS limited to {spec.blas_threads} thread(s)"
    )
    return ds
