"""A moved or copied project runs its own code: make rebuilds a venv built for another folder (its scripts
and editable install name that folder), and every job imports the project's own src/ first."""

import shutil
import subprocess

import pytest

from project_run import ROOT, copy_project, run_snakemake


def _make_tree(dest, stamp_text):
    """The files the venv rule of the Makefile reads, with a venv stamp written after them."""
    (dest / "requirements").mkdir(parents=True)
    for name in ("Makefile", "pyproject.toml", "requirements/lock.txt", "requirements/uv.txt"):
        shutil.copy2(ROOT / name, dest / name)
    (dest / ".venv").mkdir()
    (dest / ".venv" / ".installed").write_text(stamp_text)
    return dest


def _make_dry_run(tree):
    proc = subprocess.run(["make", "-n", "setup"], cwd=tree, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_make_rebuilds_a_venv_built_for_another_folder(tmp_path):
    moved = _make_tree(tmp_path / "moved", "/somewhere/else/stickslip\n")
    plan = _make_dry_run(moved)
    assert "rm -rf .venv" in plan and "venv --without-pip" in plan, plan
    assert "built for '/somewhere/else/stickslip'" in plan and str(moved) in plan, plan


def test_make_keeps_a_venv_built_for_this_folder(tmp_path):
    here = tmp_path / "here"
    here.mkdir()
    _make_tree(here, f"{here}\n")
    assert "rm -rf .venv" not in _make_dry_run(here)


def test_the_venv_imports_this_projects_package():
    python = ROOT / ".venv" / "bin" / "python"
    if not python.exists():
        pytest.skip("no .venv (make setup builds it)")
    out = subprocess.run(
        [str(python), "-c", "import stickslip; print(stickslip.__file__)"],
        capture_output=True,
        text=True,
        cwd="/",
        check=True,
    ).stdout.strip()
    assert out == str(ROOT / "src" / "stickslip" / "__init__.py")


@pytest.mark.pipeline
def test_a_job_in_a_copied_project_runs_the_copys_code(tmp_path):
    """Snakemake from this project's venv on a copy whose package says another version: the dataset the
    job writes records the copy's version (it imported the copy's src/, not this project's)."""
    from stickslip import __version__
    from stickslip.io.netcdf import read_dataset

    (tmp_path / "copy").mkdir()
    work = copy_project(tmp_path / "copy")
    version = work / "src" / "stickslip" / "_version.py"  # where the package's version lives
    text = version.read_text()
    assert f'__version__ = "{__version__}"' in text
    version.write_text(text.replace(f'__version__ = "{__version__}"', '__version__ = "9.9.9-copy"'))
    run_snakemake(work, "results/onedof/fig04/eq6.nc", timeout=600)
    source = read_dataset(work / "results/onedof/fig04/eq6.nc").attrs["source"]
    assert source.startswith("stickslip 9.9.9-copy"), source
