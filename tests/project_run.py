"""Helpers for tests that run the Snakemake pipeline on a copy of the project."""

import os
import shutil
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

import pytest
from filelock import FileLock

ROOT = Path(__file__).resolve().parents[1]


def copy_project(dest: Path) -> Path:
    """A throw-away copy of everything the pipeline reads (no results), for isolated Snakemake runs.

    Bytecode caches are copied too (with their sources' times, so they stay valid): the copy's jobs need not
    recompile the package where PYTHONDONTWRITEBYTECODE is set."""
    for name in ("Snakefile", "workflow", "config", "notebooks", "src"):
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("*.egg-info"))
        else:
            shutil.copy2(src, dest / name)
    return dest


def snakemake_command(workdir: Path, *args) -> list[str]:
    """`snakemake -j2` on the project copy in ``workdir`` with this interpreter, scheduled as `make figures`
    schedules (greedy, see the Makefile)."""
    return [
        sys.executable,
        "-m",
        "snakemake",
        "-j2",
        "--scheduler",
        "greedy",
        "--directory",
        str(workdir),
        "--snakefile",
        str(workdir / "Snakefile"),
        *args,
    ]


def run_snakemake(workdir: Path, *args, check=True, timeout=1200, hash_seed: int | None = None):
    """Snakemake on the project copy in ``workdir`` (``hash_seed``: its and every job's PYTHONHASHSEED)."""
    cmd = snakemake_command(workdir, *args)
    env = None if hash_seed is None else {**os.environ, "PYTHONHASHSEED": str(hash_seed)}
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
    if check and proc.returncode != 0:
        raise AssertionError(
            f"snakemake failed ({proc.returncode}):\n{proc.stdout[-4000:]}\n{proc.stderr[-4000:]}"
        )
    return proc


def small_config_args(workdir: Path, *extra: Path) -> list[str]:
    """``--configfile`` arguments of the small CI configuration (plus any override files, applied last)."""
    files = sorted(str(p) for p in (workdir / "config" / "test").glob("*.yaml")) + [str(p) for p in extra]
    return ["--configfile", *files] if files else []


def start_snakemake(workdir: Path, *args, log: Path):
    """Snakemake in its own process group (so a test can kill it and every job it started)."""
    cmd = snakemake_command(workdir, *args)
    fh = open(log, "w")
    return subprocess.Popen(cmd, stdout=fh, stderr=subprocess.STDOUT, start_new_session=True)


_SMALL_RUNS: dict[str, Path] = {}
#: The hash seed of the shared small run (tests/end_to_end/test_determinism.py builds again under another).
SHARED_RUN_HASH_SEED = 0


def session_root(tmp_path_factory) -> Path:
    """A folder every pytest-xdist worker of this session sees (the workers' own temp folders' parent)."""
    base = tmp_path_factory.getbasetemp()
    return base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base


@contextmanager
def session_lock(tmp_path_factory, name: str):
    """Held by one test at a time across every xdist worker of the session."""
    with FileLock(str(session_root(tmp_path_factory) / f"{name}.lock")):
        yield


def shared_small_run(tmp_path_factory) -> Path:
    """One complete run of the small configuration per test session, shared by every module and every
    xdist worker that reads it: the first to ask builds it, the others wait for it under a file lock and
    then only read it (dry runs, --summary, datasets). Built under PYTHONHASHSEED 0 (the determinism test
    builds again under 1)."""
    if "run" not in _SMALL_RUNS:
        work = session_root(tmp_path_factory) / "small_run"
        done = work.with_name("small_run.done")
        with session_lock(tmp_path_factory, "small_run"):
            if not done.exists():
                shutil.rmtree(work, ignore_errors=True)
                work.mkdir()
                run_snakemake(copy_project(work), *small_config_args(work), hash_seed=SHARED_RUN_HASH_SEED)
                done.touch()
        _SMALL_RUNS["run"] = work
    return _SMALL_RUNS["run"]


def datasets(workdir: Path) -> list[Path]:
    """Every netCDF dataset a run wrote, relative to its results folder."""
    from stickslip.io.compare import datasets as under

    return under(workdir / "results")


def decisions_flipped_within_spread(workdir: Path) -> list[str]:
    """The build's own spread check (stickslip.claims.flips, rule claims_check) on a run's results: claims
    whose decision flips when every claimed metric moves to its ensemble minimum or maximum."""
    from glob import glob

    from stickslip.claims.flips import flipped_decisions
    from stickslip.claims.load import load_claims
    from stickslip.claims.models import annotate, read_comparison
    from stickslip.claims.table import read_table
    from stickslip.io.netcdf import read_dataset

    # as the claims table: rows the beam may not decide (the model comparison) stay undecided
    comparison = read_comparison(workdir / "results" / "fe" / "model_comparison.csv")
    claims = annotate(load_claims(glob(str(workdir / "config" / "claims" / "*.yaml"))), comparison)
    readings = sorted(
        {r["reading"] for r in read_table(workdir / "results" / "claims" / "deviations.csv")} - {""}
    )
    return flipped_decisions(claims, readings, lambda path: read_dataset(os.path.join(workdir, path)))


def data_differences_in_subprocess(root_a: Path, root_b: Path, paths) -> dict[str, list[str]]:
    """``data_differences`` of many dataset pairs, computed in a fresh interpreter.

    Opening hundreds of netCDF files in the long-lived test process (after the compliance checker has
    opened them all through netCDF4 directly) crashed HDF5 once (a segfault in open_dataset); a fresh
    process per comparison batch keeps one library state per run."""
    import json

    code = (
        "import json, sys; from pathlib import Path; "
        "from stickslip.io.compare import data_differences; a, b = Path(sys.argv[1]), Path(sys.argv[2]); "
        "print(json.dumps({p: data_differences(a / p, b / p) for p in json.loads(sys.argv[3])}))"
    )
    args = [sys.executable, "-c", code, str(root_a), str(root_b)]
    proc = subprocess.run([*args, json.dumps([str(p) for p in paths])], capture_output=True, text=True)
    if proc.returncode != 0:
        raise AssertionError(f"comparison failed ({proc.returncode}):\n{proc.stderr[-3000:]}")
    return json.loads(proc.stdout)


def require_ccx():
    """CalculiX's ``ccx`` for a test: a failure under CI (.ci/run installs it), a skip elsewhere."""
    if shutil.which("ccx") is not None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("ccx (Debian package calculix-ccx) is missing under CI=true: .ci/run installs it")
    pytest.skip("ccx (CalculiX, Debian package calculix-ccx) is not installed (outside CI these tests skip)")


#: one FE scene that integrates long enough to be killed mid-way (~6-15 s per ensemble member, by machine),
#: so a kill meets it integrating also where the compiled kernels are fast; the reading's other scenes keep
#: the small configuration's 4 ms (the job costs its slowest scene, not every scene at 1.2 s)
SLOW_SCENE = "section9_kinematic_0p5mm_s"
SLOW_TARGET = f"results/fe/lower_face_drop/{SLOW_SCENE}.nc"


def slow_fe_project(tmp_path: Path) -> tuple[Path, list[str]]:
    """A copy of the project whose SLOW_SCENE runs 3 s, with the friction table (the scene's input, not under
    test) built: (the copy, the small config's arguments with the slow overlay)."""
    import yaml

    (tmp_path / "project").mkdir()
    work = copy_project(tmp_path / "project")
    slow = work / "slow.yaml"
    slow.write_text(
        yaml.safe_dump({"fe": {"scenes": {SLOW_SCENE: {"solver": {"t_end": 3.0, "output_dt": 1.0e-3}}}}})
    )
    args = small_config_args(work, slow)
    run_snakemake(work, "results/onedof/friction_mu_vr.csv", *args)
    return work, args
