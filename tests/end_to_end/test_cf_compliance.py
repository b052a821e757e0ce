"""One netCDF dataset of every kind the small configuration writes passes the CF-1.10 suite of the IOOS
compliance-checker (a kind: the same set of variables; the checker is slow, quadratic in the variables, and
datasets of one kind differ only in their numbers). Every dataset's units parse in UDUNITS-2.

Runs offline (the checker and its UDUNITS-backed cf-units come from PyPI wheels). One waiver, stated here
rather than hidden: the datasets' ``time`` is elapsed simulated time in ``s`` (the paper's runs have no
calendar date). The checker treats any coordinate named ``time`` as a calendar axis and asks for
``<unit> since <epoch>``; inventing an epoch would make every xarray reader decode the axis to dates, so
those two findings (CF 3.1 / 4.4 on ``time`` with units ``s``) are accepted and everything else must pass.
"""

import multiprocessing
import re
from concurrent.futures import ProcessPoolExecutor

import pytest

from cf_check import cf_findings
from project_run import datasets, shared_small_run

TIME_WAIVER = (
    "§3.1 Units: time must be in a valid units format <unit> since <epoch> not s",
    "§4.4 Time Coordinate: time does not have correct time units",
)


def _relevant(findings):
    return [f for f in findings if not any(w in f for w in TIME_WAIVER)]


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    return shared_small_run(tmp_path_factory)


def kind_of(names, swept: str = "") -> tuple:
    """A dataset's kind: its variable names with the swept parameter's name, the swept value of
    ``<metric>_at_<value>`` scalars and the ``_ensemble`` and ``_full_step`` suffixes folded (the same writer
    code, other numbers: an FE metric that moved at half the time step is kept as ``<metric>_full_step``),
    plus whether it has an ensemble and whether it keeps full-step values."""
    names = list(names)
    bare = (n.removesuffix("_ensemble").removesuffix("_full_step") for n in names)
    folded = {re.sub(r"_at_[0-9a-z.+-]+$", "_at_VALUE", n) for n in bare}
    folded = {"SWEPT" if n == swept else n for n in folded}
    flags = (any(n.endswith("_ensemble") for n in names), any(n.endswith("_full_step") for n in names))
    return tuple(sorted(folded)), flags


def one_per_kind(run, paths):
    """The first dataset of each kind (``kind_of``)."""
    import xarray as xr

    kinds = {}
    for p in paths:
        with xr.open_dataset(run / "results" / p, decode_times=False) as ds:
            kinds.setdefault(kind_of(map(str, ds.variables), ds.attrs.get("sweep_parameter", "")), p)
    return sorted(kinds.values())


@pytest.mark.pipeline
def test_one_dataset_of_every_kind_passes_cf(run):
    paths = one_per_kind(run, datasets(run))
    assert len(paths) >= 10, paths
    # The checker is single-threaded and slow; both cores check files (fresh interpreters: spawn).
    with ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("spawn")) as pool:
        found = pool.map(cf_findings, [run / "results" / p for p in paths])
        failures = {str(p): _relevant(f) for p, f in zip(paths, found, strict=True)}
    failures = {p: f for p, f in failures.items() if f}
    assert not failures, "\n".join(f"{p}: {f}" for p, f in failures.items())


@pytest.mark.pipeline
def test_units_are_udunits_strings(run):
    """Every ``units`` attribute parses in UDUNITS-2 (via cf-units)."""
    import xarray as xr
    from cf_units import Unit

    bad = []
    for p in datasets(run):
        with xr.open_dataset(run / "results" / p, decode_times=False) as ds:
            for name, var in ds.variables.items():
                units = var.attrs.get("units")
                if units is None:
                    continue
                try:
                    Unit(units)
                except ValueError as exc:
                    bad.append(f"{p}:{name}: {units!r} ({exc})")
    assert not bad, bad
