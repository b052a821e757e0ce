"""Compare two results folders data array by data array: did a change of code change any result?

    python -m stickslip.io.compare RESULTS_A RESULTS_B [--without-member LABEL ...]

prints every dataset whose variables (data and coordinates) differ bit for bit, every dataset present in
only one folder, and whether the claims tables (``claims/deviations.csv``) are identical; exits 1 if
anything differs. Attributes are not compared (history and source carry timestamps and the git revision),
nor are CPU-time measurements (``is_machine_measurement``): they time the machine, not the model.

``--without-member LABEL`` leaves the perturbation-ensemble members of that label out of both sides (e.g.
``window``, a member added by a change: the rest of every dataset must then be unchanged).
"""

from __future__ import annotations

import sys
from pathlib import Path

from .netcdf import is_machine_measurement


def datasets(root: Path) -> list[Path]:
    """Every netCDF dataset under ``root`` (relative paths; unfinished hidden temporaries excluded)."""
    return sorted(p.relative_to(root) for p in Path(root).rglob("*.nc") if not p.name.startswith("."))


def without_members(ds, labels):
    """The dataset without its ensemble members of these labels (unchanged when it has no ensemble)."""
    from ..ensemble import MEMBER_DIM

    label = ds.coords.get(f"{MEMBER_DIM}_label")
    if not labels or label is None:
        return ds
    left_out = set(labels)
    kept = [i for i, name in enumerate(label.values) if str(name) not in left_out]
    ds = ds.isel({MEMBER_DIM: kept})
    return ds.assign_coords({MEMBER_DIM: ds[MEMBER_DIM].copy(data=range(len(kept)))})


def data_differences(path_a: Path, path_b: Path, skip_members=()) -> list[str]:
    """Variables whose values, dtypes or shapes differ bit for bit between two datasets (NaN equals NaN),
    ensemble members labelled in ``skip_members`` left out."""
    import numpy as np
    import xarray as xr

    out = []
    with xr.open_dataset(path_a, decode_times=False) as a, xr.open_dataset(path_b, decode_times=False) as b:
        a, b = without_members(a, skip_members), without_members(b, skip_members)
        if set(a.variables) != set(b.variables):
            return [f"variables differ: {sorted(set(a.variables) ^ set(b.variables))}"]
        for name in a.variables:
            if is_machine_measurement(str(name)):
                continue
            va, vb = a[name].values, b[name].values
            if va.dtype.kind in "USO" and vb.dtype.kind in "USO":  # text: the stored width is no result
                va, vb = va.astype(str).astype(object), vb.astype(str).astype(object)
            if va.dtype != vb.dtype or va.shape != vb.shape:
                out.append(f"{name}: {va.dtype}{va.shape} vs {vb.dtype}{vb.shape}")
            elif va.dtype.kind in "fc":
                if va.tobytes() != vb.tobytes():
                    n = int(np.sum(~((va == vb) | (np.isnan(va) & np.isnan(vb)))))
                    out.append(f"{name}: {n} values differ")
            elif not np.array_equal(va, vb):
                out.append(f"{name}: values differ")
    return out


def compare_results(root_a: Path, root_b: Path, skip_members=()) -> tuple[list[str], int]:
    """One line per difference between two results folders (none when every result is identical), and the
    number of datasets compared."""
    root_a, root_b = Path(root_a), Path(root_b)
    a, b = set(datasets(root_a)), set(datasets(root_b))
    lines = [f"only in {root_a}: {p}" for p in sorted(a - b)]
    lines += [f"only in {root_b}: {p}" for p in sorted(b - a)]
    for path in sorted(a & b):
        lines += [f"{path}: {d}" for d in data_differences(root_a / path, root_b / path, skip_members)]
    table = Path("claims") / "deviations.csv"
    if (root_a / table).is_file() or (root_b / table).is_file():
        texts = [(r / table).read_text() if (r / table).is_file() else None for r in (root_a, root_b)]
        if texts[0] != texts[1]:
            lines.append(f"{table}: differs")
    return lines, len(a | b)


def main(argv: list[str]) -> int:
    import argparse

    prog = "python -m stickslip.io.compare"
    parser = argparse.ArgumentParser(prog=prog, description=__doc__.split("\n")[0])
    parser.add_argument("results_a", type=Path)
    parser.add_argument("results_b", type=Path)
    parser.add_argument("--without-member", action="append", default=[], metavar="LABEL")
    args = parser.parse_args(argv)
    lines, n = compare_results(args.results_a, args.results_b, tuple(args.without_member))
    for line in lines:
        print(line)
    print(f"{n} datasets compared: {'identical' if not lines else f'{len(lines)} differences'}")
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
