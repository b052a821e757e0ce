"""Every `stickslip` command and Python API call README.md and docs/*.md show runs as written, from a folder
outside the project, and succeeds.

Commands are taken from ```bash blocks (a line starting with `stickslip `, its `# comment` dropped) and from
inline code spans (`` `stickslip run --mu-s 0.6` ``); Python from ```python blocks and inline
`stickslip.simulate(...)`/`help(stickslip.api)` spans. Placeholders are filled: `N` of `--figure N` with 2,
`<dataset>` with a dataset. Commands that read a build's products (`claims`, `show results/...`) get
`--root` of a small stand-in project (the config, a claims table, the dataset they name), so no build is
needed. Kept cheap: an FE window (`--t-end`) is cut to 0.01 s; the 1-DOF runs take about a second each."""

import csv
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from project_run import ROOT

STICKSLIP = Path(sys.executable).with_name("stickslip")
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
SUBCOMMANDS = ("run", "fe", "laws", "claims", "show")
#: Mentions of a subcommand by name in prose, not commands (no options): "`stickslip claims` applies ...".
BARE = {f"stickslip {c}" for c in SUBCOMMANDS}
BLOCK = re.compile(r"```(\w+)[^\n]*\n(.*?)```", re.S)
SPAN = re.compile(r"`([^`\n]+)`")
FE_WINDOW = "0.01"


def shown_commands() -> list[tuple[str, str]]:
    """(page, command line) of every stickslip command the pages show, in order, without duplicates."""
    out = []
    for page in PAGES:
        text = page.read_text()
        for lang, body in BLOCK.findall(text):
            if lang in ("bash", "sh", "console"):
                for line in body.splitlines():
                    if line.startswith("stickslip "):
                        out.append((page.name, line.split("  #")[0].split(" # ")[0].strip()))
        prose = BLOCK.sub("", text)
        for span in SPAN.findall(prose):
            if span.startswith("stickslip ") and span.split()[1] in SUBCOMMANDS and span not in BARE:
                out.append((page.name, span.strip()))
    seen, unique = set(), []
    for page, command in out:
        if command not in seen:
            seen.add(command)
            unique.append((page, command))
    return unique


def shown_python() -> list[tuple[str, str]]:
    """(page, code) of every Python block and inline API call with concrete arguments."""
    out = []
    for page in PAGES:
        text = page.read_text()
        for lang, body in BLOCK.findall(text):
            if lang == "python" and "stickslip" in body:
                out.append((page.name, body))
        for span in SPAN.findall(BLOCK.sub("", text)):
            call = re.fullmatch(r"(stickslip\.simulate(?:_fe)?\(.+\)|help\(stickslip\.\w+\))", span)
            if call and "..." not in span:
                out.append((page.name, span))
    return out


def filled(command: str, stand_in: Path, dataset: Path) -> list[str]:
    argv = shlex.split(command)[1:]
    argv = ["2" if a == "N" and i and argv[i - 1] == "--figure" else a for i, a in enumerate(argv)]
    argv = [str(dataset) if a in ("<dataset>", "DATASET", "FILE.nc") else a for a in argv]
    if argv[0] == "fe" and "--t-end" in argv:
        argv[argv.index("--t-end") + 1] = FE_WINDOW
    if argv[0] in ("claims", "show") and "--root" not in argv:
        argv += ["--root", str(stand_in)]
    return argv


@pytest.fixture(scope="module")
def stand_in(tmp_path_factory) -> tuple[Path, Path]:
    """A project folder holding what `claims` and `show` read after a build: the config, a claims table with
    Fig. 2's claims, and the baseline's dataset (written by the pipeline's writer, as its rule would)."""
    import stickslip
    from stickslip.claims.table import FIELDS
    from stickslip.io.netcdf import write_dataset

    root = tmp_path_factory.mktemp("project")
    (root / "config").symlink_to(ROOT / "config")
    table = root / "results" / "claims" / "deviations.csv"
    table.parent.mkdir(parents=True)
    with open(table, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=FIELDS, restval="")
        writer.writeheader()
        writer.writerow(
            {
                "claim": "s3_frequency",
                "reading": "consistent_caption",
                "status": "deviates",
                "reported": "0.25",
                "measured": "0.27881",
                "reason": "0.28 Hz against 0.25 Hz",
                "evidence": "evidence",
            }
        )
    dataset = root / "results" / "onedof" / "fig02" / "consistent_caption" / "exact.nc"
    ds = stickslip.simulate(scene="fig02")
    write_dataset(ds, dataset, scene={}, interpretation="", method={})
    return root, dataset


def test_the_pages_show_the_commands_this_test_runs():
    """The extraction itself: it finds the commands of USAGE.md's table and the issue's own examples."""
    commands = [c for _, c in shown_commands()]
    assert "stickslip run --mu-s 0.6 --damping 1.0" in commands
    assert "stickslip fe --scene section9_kinematic --speed 2 --t-end 0.1 -o s9_2.nc" in commands
    assert "stickslip run --scene fig06 --json" in commands and "stickslip laws" in commands
    assert any(code.startswith("help(stickslip.api)") for _, code in shown_python())


@pytest.mark.parametrize("page, command", shown_commands(), ids=lambda v: v if " " in v else None)
def test_every_shown_command_runs_from_a_folder_outside_the_project(page, command, stand_in, tmp_path):
    root, dataset = stand_in
    argv = filled(command, root, dataset)
    proc = subprocess.run([str(STICKSLIP), *argv], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"{page}: {command}\n{proc.stderr[-2000:]}"
    assert "Traceback" not in proc.stderr


@pytest.mark.parametrize("page, code", shown_python(), ids=lambda v: v.splitlines()[0][:40])
def test_every_shown_python_call_runs_from_a_folder_outside_the_project(page, code, tmp_path):
    program = code if "\n" in code else f"import stickslip\n{code}\n"
    env = {**os.environ, "PAGER": "cat", "MANPAGER": "cat"}
    proc = subprocess.run(
        [sys.executable, "-c", program], cwd=tmp_path, capture_output=True, text=True, env=env, timeout=600
    )
    assert proc.returncode == 0, f"{page}: {code}\n{proc.stderr[-2000:]}"
