"""Compare two results folders data array by data array: did a change of code change any result?

    python -m stickslip.io.compare RESULTS_A RESULTS_B [--without-member LABEL ...]

compares every file a build writes and prints each difference, and each file present in only one folder;
exits 1 if anything differs. Datasets (``.nc``) are compared variable by variable (data and coordinates, bit
for bit); every other file (tables, decks, pages, images, notebooks) byte for byte.

Left out, because they legitimately differ between two builds of the same code and config:

* dataset attributes (history and source carry timestamps and the git revision) and CPU-time variables
  (``is_machine_measurement``): they time the machine, not the model;
* ``EXCLUDED_FOLDERS``: the jobs' logs and Snakemake's benchmark records (timings);
* ``EXCLUDED_FILES``: files whose content is a measurement of the build itself (each with its reason);
* ``VOLATILE``: in the files a pattern names, the text a regular expression matches (each with its reason:
  the build time and commit a dataset preview shows, a rendered notebook's random cell and table ids and
  execution times); the rest of those files is compared byte for byte;
* hidden files (unfinished temporaries) and Snakemake's ``.snakemake_timestamp`` markers of folder outputs.

``--without-member LABEL`` leaves the perturbation-ensemble members of that label out of both sides (e.g.
``window``, a member added by a change: the rest of every dataset must then be unchanged).
"""

from __future__ import annotations

import re
import sys
from fnmatch import fnmatch
from pathlib import Path

from .netcdf import is_machine_measurement

#: Top-level folders of results/ holding one build's own record: job logs and Snakemake's benchmark timings.
EXCLUDED_FOLDERS = ("logs", "benchmarks")
#: Files whose content measures the build (fnmatch pattern of the path relative to results/ -> why).
EXCLUDED_FILES: dict[str, str] = {
    "figures/methods/*_work_precision.png": "the work-precision diagrams plot measured CPU time",
    "notebooks/methods_work_precision.*": "the methods notebook tabulates and plots measured CPU time",
    "notebooks/validation_friction_laws.*": "the friction-law validation plots measured CPU time",
}
#: (fnmatch pattern, regular expression, why): text left out of the files the pattern names.
VOLATILE: tuple[tuple[str, str, str], ...] = (
    (
        "page/datasets/*.html",
        r"(?m)^\s*(source|history): .*$|^.*cpu.*$",
        "a dataset preview shows the dataset's provenance (the commit and the time it was written) and its "
        "CPU-time attributes",
    ),
    (
        "index.html",
        r'(?m)^<p class="build">.*$',
        "the replication page names the commit and the time it was built",
    ),
    (
        "notebooks/*",
        r'cell-id=[0-9a-f]+|"id": "[0-9a-f]+"|"(iopub\.[a-z_.]+|shell\.execute_reply)": "[^"]*"'
        r"|T_[0-9a-f]{5}| at 0x[0-9a-f]+",
        "a rendered notebook's cell ids, pandas table ids and object addresses are the run's, as its times",
    ),
)


def _comparable_bytes(rel: str, data: bytes) -> bytes:
    for pattern, regex, _ in VOLATILE:
        if fnmatch(rel, pattern):
            data = re.sub(regex.encode(), b"", data)
    return data


def result_files(root: Path) -> list[Path]:
    """Every file of a build under ``root`` that ``compare_results`` compares (relative paths, sorted)."""
    root = Path(root)
    out = []
    for path in root.rglob("*"):
        rel = path.relative_to(root)
        if (
            not path.is_file()
            or any(part.startswith(".") for part in rel.parts)
            or rel.parts[0] in EXCLUDED_FOLDERS
            or any(fnmatch(rel.as_posix(), pattern) for pattern in EXCLUDED_FILES)
        ):
            continue
        out.append(rel)
    return sorted(out)


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
    number of files compared."""
    root_a, root_b = Path(root_a), Path(root_b)
    a, b = set(result_files(root_a)), set(result_files(root_b))
    lines = [f"only in {root_a}: {p}" for p in sorted(a - b)]
    lines += [f"only in {root_b}: {p}" for p in sorted(b - a)]
    for path in sorted(a & b):
        if path.suffix == ".nc":
            lines += [f"{path}: {d}" for d in data_differences(root_a / path, root_b / path, skip_members)]
        else:
            texts = [_comparable_bytes(path.as_posix(), (r / path).read_bytes()) for r in (root_a, root_b)]
            if texts[0] != texts[1]:
                lines.append(f"{path}: differs")
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
    print(f"{n} files compared: {'identical' if not lines else f'{len(lines)} differences'}")
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
