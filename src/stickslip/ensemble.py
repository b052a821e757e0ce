"""Perturbation ensembles: how much each measured number moves under changes that must not matter.

A dataset is built by a pure function of its config mapping. The ensemble calls that function on the base
mapping and on perturbed copies of it:

* ``perturbed-<seed>``: every float of the mapping multiplied by (1 + s * relative), s = +-1 drawn from a
  seeded generator (parameters, initial state, time windows, solver settings alike);
* ``step``: the step-controlling settings named in ``step_keys`` (tolerances, fixed steps, safety factors)
  multiplied by ``step_factor`` - a second time step for the time-stepping methods; left out when the
  mapping has none of them (the exact solver has no step), so it never duplicates the base run;
* ``blas-threads-<n>``: the base mapping run with the BLAS limited to ``n`` threads (a different summation
  order in every BLAS call).

Every data variable on no time axis (the metrics) gets a companion ``<name>_ensemble`` with a
leading ``ensemble_member`` dimension holding the value of every member (the base run first). The claims
table takes its ``spread`` from these: a claim whose margin to its threshold is within 3 spreads is
``indistinguishable`` - never reproduced or deviating by luck.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace

import numpy as np
import xarray as xr

MEMBER_DIM = "ensemble_member"
SUFFIX = "_ensemble"

#: Settings that control a time step or an error tolerance (1-DOF methods and the FE solvers).
DEFAULT_STEP_KEYS = ("rtol", "atol", "h", "max_step", "safety_factor", "eta", "first_step")


@dataclass(frozen=True)
class EnsembleSpec:
    """What the ensemble perturbs. ``members`` = 0 switches the ensemble off (base run only)."""

    relative: float = 1e-12
    seeds: tuple[int, ...] = (1, 2)
    step_factor: float = 0.5
    step_keys: tuple[str, ...] = DEFAULT_STEP_KEYS
    blas_threads: int | None = 1

    def __post_init__(self):
        if not (np.isfinite(self.relative) and 0 < self.relative < 1e-3):
            raise ValueError(f"ensemble.relative: must be in (0, 1e-3), got {self.relative!r}")
        if not (np.isfinite(self.step_factor) and 0 < self.step_factor < 1):
            raise ValueError(f"ensemble.step_factor: must be in (0, 1), got {self.step_factor!r}")
        if self.blas_threads is not None and int(self.blas_threads) < 1:
            raise ValueError(f"ensemble.blas_threads: must be >= 1, got {self.blas_threads!r}")

    def without_blas(self) -> EnsembleSpec:
        """For computations that make no BLAS calls (the 1-DOF solvers: a test shows their output
        bit-identical under any BLAS thread count), where that member would only repeat the base run."""
        return replace(self, blas_threads=None)

    @classmethod
    def from_mapping(cls, data: Mapping | None) -> EnsembleSpec:
        """From the ``ensemble`` config section (its keys and types checked by the typed config layer)."""
        data = {k: v for k, v in (data or {}).items() if v is not None}
        for key in ("seeds", "step_keys"):
            if key in data:
                data[key] = tuple(data[key])
        return cls(**data)


def _scale_floats(node, factor: Callable[[], float], keys: tuple[str, ...] | None, under_key=None):
    """Copy of a nested mapping with floats multiplied by ``factor()``; only keys in ``keys`` if given.
    Integers and booleans are counts and switches, never perturbed."""
    if isinstance(node, Mapping):
        return {k: _scale_floats(v, factor, keys, k) for k, v in node.items()}
    if isinstance(node, list):
        return [_scale_floats(v, factor, keys, under_key) for v in node]
    if isinstance(node, float) and not isinstance(node, bool):
        if keys is None or under_key in keys:
            return node * factor()
    return node


def perturbed_mapping(mapping: Mapping, relative: float, seed: int) -> dict:
    """Every float times (1 +- relative), the sign drawn per value from ``seed`` (reproducible)."""
    rng = np.random.default_rng(seed)
    return _scale_floats(copy.deepcopy(dict(mapping)), lambda: 1.0 + relative * rng.choice((-1.0, 1.0)), None)


def step_mapping(mapping: Mapping, factor: float, keys: tuple[str, ...]) -> dict | None:
    """The mapping with its step/tolerance settings times ``factor``; None when it has none."""
    scaled = _scale_floats(copy.deepcopy(dict(mapping)), lambda: factor, keys)
    return None if scaled == dict(mapping) else scaled


def members(mapping: Mapping, spec: EnsembleSpec) -> list[tuple[str, dict, int | None]]:
    """(label, mapping, BLAS thread limit) of every member, the base run first."""
    out = [("base", dict(mapping), None)]
    out += [(f"perturbed-{s}", perturbed_mapping(mapping, spec.relative, s), None) for s in spec.seeds]
    stepped = step_mapping(mapping, spec.step_factor, spec.step_keys)
    if stepped is not None:
        out.append(("step", stepped, None))
    if spec.blas_threads is not None:
        out.append((f"blas-threads-{spec.blas_threads}", dict(mapping), int(spec.blas_threads)))
    return out


def _run(build: Callable[[dict], xr.Dataset], mapping: dict, threads: int | None) -> xr.Dataset:
    if threads is None:
        return build(mapping)
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=threads, user_api="blas"):
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
        values = []
        for ds in datasets:
            if name in ds and ds[name].shape == var.shape:
                values.append(np.asarray(ds[name].values, dtype=float))
            else:
                values.append(np.full(var.shape, np.nan))
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
    build: Callable[[dict], xr.Dataset], mapping: Mapping, spec: EnsembleSpec | None
) -> xr.Dataset:
    """``build(mapping)`` with the ensemble's member values attached (see the module docstring)."""
    if spec is None:
        return build(dict(mapping))
    runs = members(mapping, spec)
    datasets = [_run(build, m, threads) for _, m, threads in runs]
    ds = stack_members(datasets, [label for label, _, _ in runs])
    ds.attrs["ensemble"] = (
        f"{len(runs)} members: base, every float x (1 +- {spec.relative:g}) for seeds {list(spec.seeds)}, "
        f"step settings {list(spec.step_keys)} x {spec.step_factor:g} where present, "
        f"BLAS limited to {spec.blas_threads} thread(s)"
    )
    return ds


def member_values(ds: xr.Dataset, name: str) -> np.ndarray | None:
    """Values of metric ``name`` per member (leading axis), or None when the dataset has no ensemble."""
    key = name + SUFFIX
    if key not in ds:
        return None
    return np.asarray(ds[key].values, dtype=float)
