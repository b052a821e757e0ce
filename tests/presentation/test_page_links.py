"""The replication page's links open something readable: a dataset's ``stickslip show`` text, the repository
file of a rule or function, with the line of its definition in the link text."""

import html
import re
import textwrap
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.io.netcdf import write_dataset
from stickslip.presentation.page import PageBuilder, Source, source_modules
from stickslip.presentation.show import show_text
from stickslip.presentation.sources import definition_lines, rule_line

ROOT = Path(__file__).resolve().parents[2]

MODULE = '''\
"""A plotting module."""
import functools


def helper():
    return 1


@functools.lru_cache
def draw_figure(ds):
    """Decorated: the anchor is the def, not the decorator."""
    return ds


class Styler:
    pass
'''

SCRIPT = """\
from stickslip.presentation.drawing import draw_figure, Styler, CONSTANT  # noqa: E402
from stickslip.io.netcdf import read_dataset
"""

RULES = '''\
for _figure in ["fig02", "fig03"]:

    rule:
        """One figure."""
        name:
            f"draw_{_figure}"
        output:
            f"results/figures/{_figure}/a.png",
        script:
            "../scripts/draw.py"


rule summary_table:
    output:
        "results/table.csv",
'''


def _project(tmp_path: Path) -> Path:
    """A project folder with a rules file, a script, the module it imports and one dataset."""
    (tmp_path / "src/stickslip/presentation").mkdir(parents=True)
    (tmp_path / "src/stickslip/presentation/drawing.py").write_text(MODULE + "\nCONSTANT = 3\n")
    (tmp_path / "src/stickslip/io").mkdir()
    (tmp_path / "src/stickslip/io/netcdf.py").write_text((ROOT / "src/stickslip/io/netcdf.py").read_text())
    (tmp_path / "workflow/scripts").mkdir(parents=True)
    (tmp_path / "workflow/scripts/draw.py").write_text(SCRIPT)
    (tmp_path / "workflow/rules").mkdir(parents=True)
    (tmp_path / "workflow/rules/draw.smk").write_text(RULES)
    (tmp_path / "results/claims").mkdir(parents=True)
    (tmp_path / "results/claims/deviations.csv").write_text("claim,reading,status\n")
    (tmp_path / "results/figures/fig03").mkdir(parents=True)
    (tmp_path / "results/figures/fig03/a.png").write_bytes(b"")
    ds = xr.Dataset({"stick_time": ((), 1.25, {"units": "s"}), "x": ("time", np.zeros(5), {"units": "mm"})})
    write_dataset(ds, tmp_path / "results/onedof/run.nc", scene={"mu_s": 0.5}, interpretation="", method={})
    return tmp_path


def _builder(project: Path) -> PageBuilder:
    rules, script = "workflow/rules/draw.smk", "workflow/scripts/draw.py"
    source = Source("results/figures/fig03/a.png", [3], "a", "draw_fig03", rules, script)
    return PageBuilder(workdir=project, sources=[source], notebooks=[], inverse_figures={})


def _opened_line(builder: PageBuilder, link: dict) -> str:
    """The line a source link names (``..., line <n>``) of the file it opens (its href is relative to
    results/index.html)."""
    text, _, number = link["text"].rpartition(", line ")
    assert text and int(number) == link["line"], link
    return (builder.results / link["href"]).read_text().splitlines()[link["line"] - 1]


def test_a_source_link_opens_the_repository_file_and_names_the_line_of_the_def_it_is_about(tmp_path):
    builder = _builder(_project(tmp_path))
    image = builder.images(3, "a", [])[0]

    drawing = next(m for m in image["modules"] if m["text"].endswith("drawing.py"))
    assert drawing["href"] == "../src/stickslip/presentation/drawing.py"
    names = {n["text"].partition(",")[0]: n for n in drawing["names"]}
    assert list(names) == ["draw_figure", "Styler"]  # the constant has no definition line of its own
    assert [n["label"] for n in drawing["names"]] == ["draw_figure", "Styler"]  # set in code, the line not
    assert _opened_line(builder, names["draw_figure"]).startswith("def draw_figure(ds):")
    assert _opened_line(builder, names["Styler"]) == "class Styler:"

    # the rules file, at the loop's `rule:` that makes draw_fig03 (its name is an f-string)
    rule_file = image["rule_file"]
    assert rule_file["text"] == "workflow/rules/draw.smk, line 3"
    assert _opened_line(builder, rule_file).strip() == "rule:"
    # the script is linked as a whole; nothing is copied beside the page
    path = "workflow/scripts/draw.py"
    script = {"href": "../" + path, "text": path, "label": path, "line": None}
    assert image["script"] == script
    builder.write_text_pages()
    assert not (builder.results / "page" / "source").exists()


def test_rule_and_definition_lines_of_the_pipelines_own_files():
    """On the real rules and modules: a named rule, a rule made in a loop, a decorated function."""
    text = (ROOT / "workflow/rules/onedof.smk").read_text()
    smk = text.splitlines()
    assert smk[rule_line(text, "friction_table") - 1].startswith("rule friction_table:")
    loop = rule_line(text, "simulate_onedof_fig02")
    assert smk[loop - 1].strip() == "rule:"
    assert 'f"simulate_onedof_{_scene}"' in "\n".join(smk[loop : loop + 4])
    assert rule_line(text, "no_such_rule") is None
    module = textwrap.dedent(MODULE).splitlines()
    assert module[definition_lines(MODULE)["draw_figure"] - 1].startswith("def draw_figure")
    for path, names in source_modules(ROOT / "workflow/scripts/plot_onedof_figure.py", ROOT / "src"):
        lines = path.read_text().splitlines()
        for name, n in names:
            assert re.match(rf"(def|class) {name}\b", lines[n - 1]), (path, name, n)


def test_a_dataset_link_opens_its_show_text_beside_the_file(tmp_path):
    builder = _builder(_project(tmp_path))
    link = builder.dataset_link("results/onedof/run.nc")
    builder.write_text_pages()

    assert link["file"] == "onedof/run.nc"  # the .nc itself, relative to results/index.html
    page = builder.results / link["href"]
    assert page == builder.results / "page/datasets/onedof/run.nc.html"
    text = page.read_text()
    shown = show_text(tmp_path / "results/onedof/run.nc")
    assert "stick_time = 1.25 s" in shown and "checksum: ok" in shown
    assert f'<pre class="summary">{html.escape(shown, quote=False)}</pre>' in text.replace("&#39;", "'")
    # the preview links back to the page and to the file, both relative to where it sits
    assert 'href="../../../index.html"' in text and 'href="../../../onedof/run.nc"' in text
    # a file that is not netCDF keeps its direct link, and a missing one has none
    (tmp_path / "results/table.csv").write_text("a\n1\n")
    table = builder.dataset_link("results/table.csv")
    assert table == {"href": "table.csv", "text": "results/table.csv", "file": None}
    assert builder.dataset_link("results/missing.nc")["href"] is None


def test_a_damaged_dataset_is_previewed_as_damaged_and_the_page_still_builds(tmp_path):
    builder = _builder(_project(tmp_path))
    path = tmp_path / "results/onedof/run.nc"
    path.write_bytes(path.read_bytes()[:400])  # truncated, as by a killed copy
    link = builder.dataset_link("results/onedof/run.nc")
    builder.write_text_pages()
    text = html.unescape((builder.results / link["href"]).read_text())
    assert "checksum: MISMATCH" in text and "make repair" in text
