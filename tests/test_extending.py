"""docs/EXTENDING.md stays true: its recipes are executed as written, on a copy of the project and the small
configuration. Every ``yaml file=PATH`` block is written to PATH, every ``text append=PATH`` block appended to
PATH, and every `snakemake` command run where the page shows it, the small config files in front of the
recipe's: a dry run must list every job the paragraph after it names, the real command must write its
dataset."""

import re
import shlex

import pytest

from stickslip.io.netcdf import read_dataset

from project_run import ROOT, copy_project, run_snakemake

PAGE = ROOT / "docs" / "EXTENDING.md"
BLOCK = re.compile(r"```(?P<lang>\w+)(?: (?P<how>file|append)=(?P<path>\S+))?\n(?P<body>.*?)```\n", re.S)
JOB = re.compile(r"`((?:simulate_onedof|onedof_figure)_\w+)`")


def page_blocks():
    return list(BLOCK.finditer(PAGE.read_text()))


def commands():
    """(snakemake arguments, jobs the next paragraph names) of every command on the page."""
    out = []
    text = PAGE.read_text()
    for m in page_blocks():
        if m["lang"] != "bash":
            continue
        paragraph = text[m.end() :].lstrip("\n").split("\n\n")[0]  # the paragraph right after the command
        for line in m["body"].splitlines():
            if line.startswith(".venv/bin/snakemake"):
                out.append((shlex.split(line)[1:], JOB.findall(paragraph)))
    return out


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
    assert all(jobs for args, jobs in commands() if "-n" in args)  # every dry run promises its jobs


@pytest.mark.pipeline
def test_every_recipe_runs_on_the_small_configuration(tmp_path):
    work = copy_project(tmp_path)
    small = sorted(str(p) for p in (work / "config" / "test").glob("*.yaml"))
    listed = iter(commands())
    for m in page_blocks():  # in the page's order: a recipe's files exist from where it adds them
        if m["how"] == "file":
            (work / m["path"]).write_text(m["body"])
        elif m["how"] == "append":
            with open(work / m["path"], "a") as fh:
                fh.write(m["body"])
        if m["lang"] != "bash":
            continue
        args, jobs = next(listed)
        at, end = args.index("--configfile") + 1, args.index("--")
        files = [str(work / f) for f in args[at:end]]  # the page's paths are relative to the project folder
        proc = run_snakemake(work, *args[:at], *small, *files, *args[end:])
        if "-n" in args:
            for job in jobs:
                assert f"rule {job}:" in proc.stdout or f"localrule {job}:" in proc.stdout, (args, job)
        else:
            ds = read_dataset(work / args[-1])
            assert ds.attrs["scene_friction_law"] == "StribeckLaw(mu_s=0.5, mu_k=0.3, v_s=0.5)"
            assert ds.attrs["method_name"] == "switch" and int(ds.solver_status) == 0
