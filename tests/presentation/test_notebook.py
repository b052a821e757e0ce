"""Notebook helpers: the per-section scorecard, and the renderer that shows a reader results, not code."""

import json
import re

import nbformat
import pandas as pd
import pytest

from stickslip.claims.rows import STATUSES
from stickslip.presentation.notebook import (
    PARAMETERS_TAG,
    claims_frame,
    reader_notebook,
    render,
    render_all,
    scorecard_html,
    status_counts,
    styled_claims,
    to_html,
)
from stickslip.presentation.plots import STATUS_COLOUR

COLUMNS = ["claim", "reading", "section", "figure", "kind", "quantity", "reported", "unit", "measured"]
COLUMNS += ["deviation", "margin", "spread", "status", "expected", "matches_expected", "reason", "quote"]


def row(claim, reading, status, expected=None, margin=0.5, spread=0.01, section="5"):
    return dict(
        claim=claim,
        reading=reading,
        section=section,
        figure="Fig. 5",
        kind="value",
        quantity="frequency_peaks",
        reported=0.27,
        unit="Hz",
        measured=0.3,
        deviation=0.11,
        margin=margin,
        spread=spread,
        status=status,
        expected=expected or status,
        matches_expected=expected in (None, status),
        reason="",
        quote="q",
    )


@pytest.fixture
def table(tmp_path):
    rows = [
        row("a", "r2", "reproduced"),
        row("b", "r2", "indistinguishable", margin=1e-9, spread=4e-9),
        row("a", "r1", "deviates", expected="reproduced"),
        row("c", None, "not-comparable", margin=float("nan"), spread=float("nan")),
        row("d", "r1", "reproduced", section="6"),
    ]
    path = tmp_path / "deviations.csv"
    pd.DataFrame(rows, columns=COLUMNS).to_csv(path, index=False)
    return path


def test_every_status_has_its_own_colour():
    assert set(STATUS_COLOUR) == set(STATUSES)
    assert len(set(STATUS_COLOUR.values())) == len(STATUSES)


def test_status_counts_has_every_status_in_order_zeros_included(table):
    counts = status_counts(claims_frame(table, sections=["5"]))
    assert list(counts.columns) == [*STATUSES, "total"]
    assert list(counts.index) == ["r2", "r1", "-"]  # the table's order; "-": reading-independent
    assert counts.loc["r2"].to_dict() == {
        "reproduced": 1,
        "deviates": 0,
        "indistinguishable": 1,
        "not-comparable": 0,
        "total": 2,
    }
    assert counts.loc["r1", "deviates"] == 1 and counts.loc["-", "not-comparable"] == 1


def test_status_counts_rejects_an_unknown_status(table):
    frame = claims_frame(table)
    frame.loc[frame.index[0], "status"] = "maybe"
    with pytest.raises(ValueError, match="maybe"):
        status_counts(frame)


def test_claims_frame_filters_and_gives_old_tables_margin_and_spread(table, tmp_path):
    assert sorted(claims_frame(table, sections=["6"])["claim"]) == ["d"]
    assert sorted(claims_frame(table, claims=["a"])["reading"]) == ["r1", "r2"]
    old = tmp_path / "old.csv"
    pd.read_csv(table).drop(columns=["margin", "spread"]).to_csv(old, index=False)
    frame = claims_frame(old)
    assert frame["margin"].isna().all() and frame["spread"].isna().all()


def test_claims_table_colours_each_status_and_flags_a_changed_pin(table):
    html = styled_claims(claims_frame(table, sections=["5"])).to_html()
    headers = re.findall(r'<th [^>]*class="col_heading[^"]*"[^>]*>([^<]*)</th>', html)
    assert headers.index("status") < headers.index("reported")  # on screen without scrolling
    assert headers[headers.index("deviation") + 1 : headers.index("expected")] == ["margin", "spread"]
    for status in STATUSES:
        assert STATUS_COLOUR[status] in html, status
    assert "4e-09" in html and "1e-09" in html  # margin and spread of the indistinguishable row
    assert len(re.findall(r"(?m)^\s*color: red;", html)) == 1  # only row a/r1 differs from its pin


def test_scorecard_counts_then_table_collapsed_when_long(table):
    frame = claims_frame(table, sections=["5"])
    html = scorecard_html(frame, "Section 5 claims")
    assert html.index("Section 5 claims") < html.index("1 indistinguishable") < html.index("<details")
    assert "4 claim checks:</b> 1 reproduced, 1 deviates, 1 indistinguishable, 1 not-comparable." in html
    assert "<details open>" in html
    assert "<details open>" not in scorecard_html(frame, "x", open_rows=3)
    assert "No claim" in scorecard_html(frame.iloc[:0], "empty")
    assert "outside it (the reason column says why)" in html  # the colour legend
    assert "outside it (the reason column says why)" not in scorecard_html(frame, "again", legend=False)


def _notebook(*cells):
    nb = nbformat.v4.new_notebook()
    nb.cells = list(cells)
    return nb


def test_reader_notebook_drops_the_parameters_cell_and_folds_code():
    params = nbformat.v4.new_code_cell("PARAMS = {'secret_key_x': 1}")
    params.metadata["tags"] = [PARAMETERS_TAG]
    code = nbformat.v4.new_code_cell("print('hello')")
    code.outputs = [nbformat.v4.new_output("stream", name="stdout", text="hello\n")]
    nb = _notebook(nbformat.v4.new_markdown_cell("# Title"), params, code)
    out = reader_notebook(nb, source_link="../../notebooks/x.py")
    assert all(PARAMETERS_TAG not in c.metadata.get("tags", []) for c in out.cells)
    assert [c.cell_type for c in out.cells] == ["markdown", "markdown", "code"]
    assert "x.py" in out.cells[1].source  # the source link right under the title
    first = out.cells[2].outputs[0]["data"]["text/html"]
    assert (
        first.startswith('<details class="nb-code"><summary')
        and ">code</summary>" in first
        and "hello" in first
    )
    assert len(nb.cells) == 3 and len(code.outputs) == 1  # the executed notebook itself is untouched
    assert "secret_key_x" not in to_html(nb)


SOURCE = """# %% [markdown]
# # A section title
#
# What the paper reports.

# %%
VALUE = PARAMS.get("value", 0) * 6  # helper_definition_marker

# %%
print(f"measured {VALUE}")
"""


def test_render_executes_and_hides_code_and_parameters(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "notebooks").mkdir()
    source = tmp_path / "notebooks" / "demo.py"
    source.write_text(SOURCE)
    target = tmp_path / "results" / "notebooks" / "demo.html"
    render(source, target, {"value": 7, "marker": "injected_blob_marker"}, timeout=60)
    html = target.read_text()
    assert "measured 42" in html  # executed, with the injected parameter
    assert "injected_blob_marker" not in html and "json.loads" not in html
    assert 'class="input"' not in html and "In&nbsp;[" not in html  # no code cells, no prompts
    visible = re.sub(r'<details class="nb-code">.*?</details>', "", html, flags=re.S)
    assert "helper_definition_marker" not in visible  # the code is only inside the collapsed blocks
    assert "helper_definition_marker" in html
    assert visible.index("A section title") < visible.index("measured 42")
    assert 'href="../../notebooks/demo.py"' in html
    assert "<title>A section title</title>" in html
    executed = nbformat.read(target.with_suffix(".ipynb"), as_version=4)
    tagged = [c for c in executed.cells if PARAMETERS_TAG in c.metadata.get("tags", [])]
    assert len(tagged) == 1 and json.dumps("injected_blob_marker") in tagged[0].source


def test_render_all_renders_the_rest_when_one_fails_and_logs_why(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "notebooks").mkdir()
    good, bad = tmp_path / "notebooks" / "good.py", tmp_path / "notebooks" / "bad.py"
    good.write_text(SOURCE)
    bad.write_text(SOURCE.replace('print(f"measured {VALUE}")', 'raise ValueError("broken_cell_marker")'))
    out, logs = tmp_path / "results", tmp_path / "logs"
    logs.mkdir()
    jobs = [
        (bad, out / "bad.html", {"value": 1}, logs / "bad.log"),
        (good, out / "good.html", {"value": 7}, logs / "good.log"),
    ]
    failed = render_all(jobs, workers=2, timeout=60)
    assert failed == [str(bad)]
    assert "measured 42" in (out / "good.html").read_text()
    assert not (out / "bad.html").exists()  # nothing half-written for the failed one
    assert "broken_cell_marker" in (logs / "bad.log").read_text()
    assert "good.html" in (logs / "good.log").read_text()


def test_claims_table_shows_the_papers_words_beside_its_numbers(tmp_path):
    """A comparison's reported cell is the paper's statement, a value's its number: the table shows both
    (the rendered Section 3-7 notebooks once failed on a words cell formatted as a number)."""
    compared = {**row("b", "r1", "deviates"), "kind": "compare", "reported": "x > y"}
    rows = [row("a", "r1", "reproduced"), compared]
    path = tmp_path / "mixed.csv"
    pd.DataFrame(rows, columns=COLUMNS).to_csv(path, index=False)
    cells = re.findall(r'class="data row\d+ col\d+" >([^<]*)<', styled_claims(claims_frame(path)).to_html())
    assert "0.27" in cells and "x > y" in cells
