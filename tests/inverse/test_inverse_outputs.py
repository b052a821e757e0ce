"""The inverse study's files: every variable of every dataset has UDUNITS units, a parameter on a ridge is a
range (never a point), and the minimal conflicting subsets in the datasets equal those in conflicts.csv."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

from stickslip.inverse.dataset import ABSENT, RAGGED, figure_dataset
from stickslip.inverse.outputs import write_study
from stickslip.inverse.problem import PARAMS, build_problem, load_claim_rows
from stickslip.inverse.study import fit_problem, run_study
from stickslip.io.netcdf import read_dataset
from stickslip.schema import InverseJob, InverseOnedof

ROOT = Path(__file__).resolve().parents[2]


def unitless_variables(path: Path) -> list[str]:
    """Variables of a dataset without a UDUNITS-2 ``units`` attribute (string labels are not quantities:
    CF 3.1 asks units of numeric variables only)."""
    from cf_units import Unit

    bad = []
    with xr.open_dataset(path) as ds:
        for name, var in ds.variables.items():
            if var.dtype.kind in "OSU":
                continue
            units = var.attrs.get("units")
            try:
                Unit(units)
            except (TypeError, ValueError):
                bad.append(f"{path.name}:{name}: {units!r}")
            if not units:
                bad.append(f"{path.name}:{name}: no units")
    return bad


def ci_config_and_claims() -> tuple[InverseJob, dict]:
    """The study's configuration at CI size (config/test/inverse.yaml, no corner plots) and the claims."""
    from stickslip.pipeline.config import merge

    sections = {}
    for name in ("config.yaml", "inverse.yaml"):
        sections.update(yaml.safe_load((ROOT / "config" / name).read_text()))
    test = yaml.safe_load((ROOT / "config" / "test" / "inverse.yaml").read_text())
    sections["inverse"] = merge(sections["inverse"], test["inverse"])
    sections["inverse"]["settings"]["default"]["corner"] = []
    job = {"onedof": InverseOnedof.part_of(sections["onedof"]), "inverse": sections["inverse"]}
    claims = load_claim_rows(sorted((ROOT / "config" / "claims").glob("*.yaml")))
    return InverseJob.model_validate(job), claims


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    """Figs. 12-13 and the joint problem at CI size, written as the rule writes."""
    config, claims = ci_config_and_claims()
    out = run_study(config, claims, figures=["fig12"], families=["consistent"])
    target = tmp_path_factory.mktemp("inverse")
    write_study(out, target)
    return target


def test_every_variable_of_every_inverse_dataset_has_units(study):
    paths = sorted(study.glob("*.nc"))
    assert [p.stem for p in paths] == ["fig12", "joint"]
    assert not [b for p in paths for b in unitless_variables(p)]


def test_a_parameter_that_is_not_identified_is_a_range_never_a_point(study):
    with read_dataset(study / "fig12.nc") as ds:
        checked = 0
        for fam in ds.family.values:
            sub = ds.sel(family=fam)
            for j, param in enumerate(PARAMS):
                if not np.isfinite(sub[f"fit_point_{param}"]):
                    continue  # not free in this fit
                lo, hi = float(sub[f"flat_lower_{param}"]), float(sub[f"flat_upper_{param}"])
                if int(sub.on_ridge.isel(parameter=j)):
                    assert np.isnan(sub[f"best_fit_{param}"]) and lo < hi
                    checked += 1
                else:  # identified: a point inside its profile-likelihood interval
                    assert lo * (1 - 1e-9) <= float(sub[f"best_fit_{param}"]) <= hi * (1 + 1e-9)
        assert checked > 0  # Figs. 12-13 (two numbers) leave ridges
    rows = list(csv.DictReader((study / "summary.csv").open()))
    for row in rows:
        for param in PARAMS:
            if not row.get(f"identifiable_{param}"):
                continue  # not free in this fit
            point = row[f"best_{param}"]
            assert (point == "") == (row[f"identifiable_{param}"] == "0"), (row["figure"], param)
            assert row[f"open_{param}"] in ("", "below", "above", "both")
            if point and row[f"lower_{param}"]:  # an identified parameter: its interval holds the point
                assert float(row[f"lower_{param}"]) <= float(point) <= float(row[f"upper_{param}"])
            elif not point:  # a range has both ends
                assert float(row[f"lower_{param}"]) < float(row[f"upper_{param}"]), (row["figure"], param)


def test_conflicts_csv_equals_the_datasets(study):
    rows = [r for r in csv.DictReader((study / "conflicts.csv").open()) if int(r["size"]) > 0]
    assert rows and all(r["above_noise"] in ("0", "1", "") and r["residual_noise"] != "" for r in rows)
    from_csv = sorted((r["figure"], r["family"], r["claims"]) for r in rows)
    from_ds = []
    for path in sorted(study.glob("*.nc")):
        with read_dataset(path) as ds:
            for fam in ds.family.values:
                sub = ds.sel(family=fam)
                for k in range(sub.sizes["conflict"]):
                    members = [
                        str(c) for c, m in zip(ds.claim.values, sub.conflict_member.isel(conflict=k)) if m
                    ]
                    if members:
                        assert len(members) == int(sub.conflict_size.isel(conflict=k))
                        from_ds.append((path.stem, str(fam), " + ".join(members)))
    assert from_csv == sorted(from_ds)
    numbers = list(csv.DictReader((study / "numbers.csv").open()))
    assert {r["unit"] for r in numbers if r["figure"] == "fig12"} == {"Hz"}


def test_each_family_keeps_its_own_values_in_a_figure_dataset_and_is_padded_beyond_them():
    """Figs. 2-3 at CI size, unsampled: the families profile different quantities over different numbers of
    points and find different numbers of conflicts; concatenated, each keeps exactly its own values, and
    where another family has more entries it reads as none (flags 0, no conflict, NaN)."""
    config, claims = ci_config_and_claims()
    settings = config.inverse.mode_settings
    results = {
        fam: fit_problem(build_problem(config, claims, "fig02", fam), settings, steps=0)
        for fam in ("consistent", "plateau")
    }
    ds = figure_dataset("fig02", results, config.inverse)
    own = {fam: r.to_dataset() for fam, r in results.items()}
    ragged = [d for d in RAGGED if own["consistent"].sizes[d] != own["plateau"].sizes[d]]
    assert {"profile_point", "conflict"} <= set(ragged) and ds.sizes["sample"] == 1
    padded = 0
    for fam, part in own.items():
        for name in part.data_vars:
            got = ds[name].sel(family=fam)
            if "quantity" in part[name].dims:
                got = got.sel(quantity=part.quantity.values)
            inside = got.isel({d: slice(0, part.sizes[d]) for d in part[name].dims if d in RAGGED})
            np.testing.assert_array_equal(inside.values, part[name].values, err_msg=f"{fam} {name}")
            attrs = part[name].attrs
            assert got.dtype == part[name].dtype and list(got.attrs) == list(attrs)
            assert all(np.array_equal(got.attrs[k], attrs[k]) for k in attrs), name
            if inside.ndim != 1 or inside.size == got.size:
                continue
            beyond = got.values[inside.size :]
            assert np.all(beyond == ABSENT[name]) if name in ABSENT else np.all(np.isnan(beyond)), name
            padded += 1
    assert padded > 0


@pytest.mark.pipeline
def test_every_dataset_of_a_build_under_results_inverse_has_units(tmp_path_factory):
    """The same check on the datasets a whole (small) build wrote."""
    from project_run import shared_small_run

    paths = sorted((shared_small_run(tmp_path_factory) / "results" / "inverse").glob("*.nc"))
    assert len(paths) >= 2
    assert not [b for p in paths for b in unitless_variables(p)]
