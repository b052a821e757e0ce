"""docs/EXTENDING.md stays true: its recipes are executed as written, on a copy of the project and the small
configuration. Every ``yaml file=PATH`` block is written to PATH, every ``text append=PATH`` block appended to
PATH, and every `snakemake` command run where the page shows it, the small config files in front of the
recipe's: a dry run must list every job the paragraph after it names, the real command must write its
dataset."""

import re
import shlex
import subprocess
import sys

import pytest

from stickslip.io.netcdf import read_dataset

from project_run import ROOT, copy_project, run_snakemake

PAGE = ROOT / "docs" / "EXTENDING.md"
BLOCK = re.compile(r"```(?P<lang>\w+)(?: (?P<how>file|append)=(?P<path>\S+))?\n(?P<body>.*?)```\n", re.S)
JOB = re.compile(r"`((?:simulate_onedof|onedof_figure)_\w+)`")


def page_blocks():
    return list(BLOCK.finditer(PAGE.read_text()))


def commands():
    """(snakemake arguments, jobs the next paragraph names) of every command on the page; a `make small`
    line as the Makefile passes it on (``--in`` folder, targets, overlay files), with its variables."""
    out = []
    text = PAGE.read_text()
    for m in page_blocks():
        if m["lang"] != "bash":
            continue
        paragraph = text[m.end() :].lstrip("\n").split("\n\n")[0]  # the paragraph right after the command
        for line in m["body"].splitlines():
            if line.startswith(".venv/bin/snakemake"):
                out.append((shlex.split(line)[1:], JOB.findall(paragraph)))
            elif line.startswith("make small "):
                out.append((dict(w.split("=", 1) for w in shlex.split(line)[2:]), []))
    return out


def make_small(work, small, variables):
    """What `make small` runs (test_make_small_passes_its_variables_on below checks the Makefile says
    so), in the copy ``work``: the build wrapper in its own folder."""
    overlay = [str(work / f) for f in variables["OVERLAY"].split()]
    cmd = [sys.executable, "-m", "stickslip.pipeline.build", "--in", variables["OVERLAY_DIR"]]
    cmd += [sys.executable, "-m", "snakemake", "-j2", "--scheduler", "greedy", *variables["TARGETS"].split()]
    proc = subprocess.run([*cmd, "--configfile", *small, *overlay], cwd=work, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return work / variables["OVERLAY_DIR"]


def test_make_small_passes_its_variables_on():
    proc = subprocess.run(
        ["make", "-n", "small", "OVERLAY=config/test/onedof.yaml", "OVERLAY_DIR=build/x", "TARGETS=a b"],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    line = " ".join(proc.stdout.replace("\\\n", " ").split())
    assert "-m stickslip.pipeline.build --in build/x " in line, proc.stdout
    assert f"a b --configfile {ROOT}/config/test/onedof.yaml" in line, proc.stdout


def test_the_page_has_the_four_recipes_and_their_commands():
    text = PAGE.read_text()
    for title in (
        "## A new scene",
        "## A new friction law in a scene",
        "## A new claim",
        "## A new paper figure",
    ):
        assert title in text
    assert len(commands()) == 4
    assert all(jobs for args, jobs in commands() if isinstance(args, list))  # every dry run promises its jobs
    assert not [
        m["path"]
        for m in page_blocks()
        if m["path"] and m["path"].startswith("config/") and not m["path"].startswith("config/claims/")
    ], "a trial's file in config/ joins every build"


@pytest.mark.pipeline
def test_every_recipe_runs_on_the_small_configuration(tmp_path):
    work = copy_project(tmp_path)
    small = sorted(str(p) for p in (work / "config" / "test").glob("*.yaml"))
    listed = iter(commands())
    for m in page_blocks():  # in the page's order: a recipe's files exist from where it adds them
        if m["how"] == "file":
            (work / m["path"]).parent.mkdir(parents=True, exist_ok=True)
            (work / m["path"]).write_text(m["body"])
        elif m["how"] == "append":
            with open(work / m["path"], "a") as fh:
                fh.write(m["body"])
        if m["lang"] != "bash":
            continue
        args, jobs = next(listed)
        if isinstance(args, dict):
            folder = make_small(work, small, args)
            ds = read_dataset(folder / args["TARGETS"])
            assert ds.attrs["scene_friction_law"] == "StribeckLaw(mu_s=0.5, mu_k=0.3, v_s=0.5)"
            assert ds.attrs["method_name"] == "switch" and int(ds.solver_status) == 0
            assert not (work / "results").exists()  # the project's own results/ untouched
            continue
        at, end = args.index("--configfile") + 1, args.index("--")
        files = [str(work / f) for f in args[at:end]]  # the page's paths are relative to the project folder
        assert "-n" in args, f"{args}: a real build of an overlay runs in its own folder (make small)"
        proc = run_snakemake(work, *args[:at], *small, *files, *args[end:])
        for job in jobs:
            assert f"rule {job}:" in proc.stdout or f"localrule {job}:" in proc.stdout, (args, job)
