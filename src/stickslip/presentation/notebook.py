"""Helpers for the comparison notebooks: the claims tables they show and how they are rendered.

The notebooks in ``notebooks/`` are a paper's supplement: they read the pipeline's results and show them
next to what the paper reports. This module holds what they share that is not a figure (figures are in
``presentation.plots``): reading the deviations table, the per-section *scorecard* (status counts per reading,
then the colour-coded claims table with each claim's margin to its threshold and its ensemble spread), and
``render``, which executes a jupytext notebook and writes HTML for a reader: no code cells (each cell's code
a click away in a collapsed block, the notebook's source linked at the top) and no injected parameters.
"""

from __future__ import annotations

import html
import json
import os
from pathlib import Path

from stickslip.catalogue import figure_verdicts as figure_verdicts_path
from stickslip.catalogue import page
from stickslip.claims.rows import STATUSES
from stickslip.presentation.plots import STATUS_COLOUR

#: Columns of the claims table a notebook shows, in order (the status early, so it is on screen).
CLAIM_COLUMNS = (
    "claim",
    "reading",
    "figure",
    "status",
    "quantity",
    "reported",
    "measured",
    "reference",
    "unit",
    "deviation",
    "margin",
    "spread",
    "expected",
    "reason",
)

#: A claims table longer than this is shown collapsed under its scorecard (counts stay visible).
OPEN_ROWS = 25

#: Tag of the cell holding the pipeline's injected parameters: executed, never shown.
PARAMETERS_TAG = "injected-parameters"

#: A <summary> with its disclosure triangle (the classic nbconvert template's CSS hides it otherwise).
SUMMARY_STYLE = "display: list-item; cursor: pointer"


def claims_readings(params: dict, config_path: str = "config/config.yaml") -> list[str]:
    """Readings a notebook shows: those the pipeline injected, else the config's claims readings."""
    if params.get("claims_readings"):
        return list(params["claims_readings"])
    import yaml

    with open(config_path) as fh:
        return list(yaml.safe_load(fh)["claims"]["readings"])


def claims_frame(csv_path, sections=None, claims=None):
    """The deviations table (optionally filtered by section or claim id) as a pandas DataFrame.

    Reading-independent rows get the reading ``-``. A table written before the ``margin``/``spread``
    columns existed gets them as NaN, so every notebook shows the same columns."""
    import pandas as pd

    frame = pd.read_csv(csv_path, dtype={"section": str}).fillna({"reading": "-"})
    for col in ("margin", "spread"):
        if col not in frame:
            frame[col] = float("nan")
    if sections is not None:
        frame = frame[frame["section"].isin([str(s) for s in sections])]
    if claims is not None:
        frame = frame[frame["claim"].isin(claims)]
    return frame


def reported_value(frame, claim):
    """The paper's number of a claim row in the deviations table (None when the claim is not in the table)."""
    rows = frame[frame["claim"] == claim]
    return float(rows["reported"].iloc[0]) if len(rows) else None


def status_counts(frame):
    """Claim checks per reading (rows, in the table's order) and status (columns, every status of
    ``STATUSES`` in that order, zeros included), with a ``total`` column: the compact scorecard of a
    section."""
    import pandas as pd

    counts = pd.crosstab(frame["reading"], frame["status"]) if len(frame) else pd.DataFrame()
    unknown = set(counts.columns) - set(STATUSES)
    if unknown:
        raise ValueError(f"status: {sorted(unknown)} not one of {STATUSES}")
    order = list(dict.fromkeys(frame["reading"]))  # readings in the table's order
    counts = counts.reindex(index=order, columns=list(STATUSES), fill_value=0).astype(int)
    counts["total"] = counts.sum(axis=1)
    counts.index.name = "reading"
    counts.columns.name = None
    return counts


def _status_style(status) -> str:
    return f"background-color: {STATUS_COLOUR.get(status, 'white')}"


def styled_counts(counts):
    """The status counts with each status column coloured like its status (a zero count left white)."""
    styler = counts.style.map_index(
        lambda v: _status_style(v) if v in STATUS_COLOUR else "font-weight: bold", axis="columns"
    )
    for status in STATUSES:
        styler = styler.map(lambda v, s=status: _status_style(s) if v else "", subset=[status])
    return styler


def number_or_words(value) -> str:
    """A claims-table cell that holds the paper's number (4 significant digits) or its words (a comparison's
    "a > b", a trend's "increases with x")."""
    try:
        return f"{float(value):.4g}"
    except (TypeError, ValueError):
        return str(value)


def styled_claims(frame):
    """The claims table, status cells coloured; a status that differs from its pin is in bold red text.

    ``margin`` is the distance of the measured decision variable to the claim's threshold, ``spread`` its
    range over the perturbation ensemble (``–``: no ensemble); a margin within 3 spreads is
    ``indistinguishable``."""
    cols = [c for c in CLAIM_COLUMNS if c in frame]

    def colour(row):
        styles = [""] * len(row)
        i = list(row.index).index("status")
        styles[i] = _status_style(row["status"])
        if "expected" in row and row["status"] != row["expected"]:
            styles[i] += "; color: red; font-weight: bold"
        return styles

    return (
        frame[cols]
        .style.apply(colour, axis=1)
        .format(
            {
                "reported": number_or_words,
                "measured": "{:.4g}",
                "reference": "{:.4g}",
                "deviation": "{:+.1%}",
                "margin": "{:.3g}",
                "spread": "{:.3g}",
            },
            na_rep="–",
        )
        .set_table_styles(
            [
                {"selector": "", "props": [("font-size", "0.85em")]},
                {"selector": "td, th", "props": [("white-space", "nowrap")]},
            ]
        )
        .set_properties(subset=[c for c in ("quantity", "reason") if c in cols], **{"text-align": "left"})
        .set_properties(
            subset=[c for c in ("reason",) if c in cols], **{"white-space": "normal", "min-width": "30em"}
        )
        .hide(axis="index")
    )


def legend_html() -> str:
    """One line naming each status colour."""
    meaning = {
        "reproduced": "within the claim's tolerance",
        "deviates": "outside it (the reason column says why)",
        "indistinguishable": "within 3× the ensemble spread of the threshold: the numbers cannot decide",
        "not-comparable": "nothing to measure, or the paper contradicts itself",
    }
    items = [
        f'<span style="{_status_style(s)}; padding: 0 0.4em; border: 1px solid #999">{s}</span> '
        f"{html.escape(meaning.get(s, ''))}"
        for s in STATUSES
    ]
    return '<p style="font-size: 0.9em">' + " &nbsp; ".join(items) + "</p>"


def scorecard_html(
    frame, title: str = "Claims of this section", open_rows: int = OPEN_ROWS, legend: bool = True
) -> str:
    """The scorecard as HTML: status counts per reading, a colour legend (unless ``legend=False``, for a
    notebook's second and later scorecards), then the claims table (collapsed under a summary line when it
    has more than ``open_rows`` rows)."""
    if not len(frame):
        return f"<h3>{html.escape(title)}</h3><p>No claim of the claims table belongs here.</p>"
    counts = status_counts(frame)
    totals = counts[list(STATUSES)].sum()
    summary = ", ".join(f"{int(totals[s])} {s}" for s in STATUSES)
    table = styled_claims(frame).to_html()
    is_open = " open" if len(frame) <= open_rows else ""
    return (
        f"<h3>{html.escape(title)}</h3>"
        f"<p><b>{len(frame)} claim checks:</b> {summary}.</p>"
        + styled_counts(counts).to_html()
        + (legend_html() if legend else "")
        + f"<details{is_open}><summary style='{SUMMARY_STYLE}'>the {len(frame)} claim checks: reported, "
        "measured, margin to the threshold, ensemble spread, status (a status in bold red differs from its "
        "pin)</summary>" + table + "</details>"
    )


def scorecard(frame, title: str = "Claims of this section", open_rows: int = OPEN_ROWS, legend: bool = True):
    """Display object of ``scorecard_html`` for a notebook cell."""
    from IPython.display import HTML

    return HTML(scorecard_html(frame, title, open_rows, legend))


VERDICTS_CSV = figure_verdicts_path()


def figure_verdicts(figures, csv_path=VERDICTS_CSV):
    """Each paper figure's verdicts as the replication page (``results/index.html``) shows them, read from
    the one table both take them from (``stickslip.claims.verdicts.figure_table``): under the primary
    reading, as printed, and the best of the readings (a search). A DataFrame, one row per figure."""
    import pandas as pd

    from stickslip.claims.table import read_table

    rows = {r["figure"]: r for r in read_table(csv_path)}
    # one column for the search: a figure with no claims searched no reading, the others the same number
    counts = [int(rows[str(n)]["readings_searched"] or 0) for n in figures if str(n) in rows]
    searched = max(counts, default=0)

    def cell(r, prefix):
        if not r[f"{prefix}_verdict"]:
            return "-"
        return f"{r[f'{prefix}_verdict']} ({r[f'{prefix}_reproduced']} of {r[f'{prefix}_decided']})"

    out = [
        {
            "figure": f"Fig. {number}",
            "verdict (primary reading)": cell(r, "primary"),
            "primary reading": r["primary_reading"],
            "as printed": cell(r, "printed"),
            f"best of {searched} readings (a search)": cell(r, "best"),
            "best reading": r["best_reading"] or "-",
            "not evidence": r["not_evidence"] or "-",
        }
        for number in figures
        if (r := rows.get(str(number))) is not None
    ]
    return pd.DataFrame(out)


#: Colours of the figure verdicts (as on the replication page).
VERDICT_COLOUR = {
    "reproduced": STATUS_COLOUR["reproduced"],
    "mostly reproduced": STATUS_COLOUR["reproduced"],
    "partly": STATUS_COLOUR["indistinguishable"],
    "deviating": STATUS_COLOUR["deviates"],
    "not comparable": STATUS_COLOUR["not-comparable"],
}


def _verdict_colour(cell: str) -> str:
    label = str(cell).split(" (")[0]
    return f"background-color: {VERDICT_COLOUR.get(label, 'white')}"


def verdicts_html(figures, csv_path=VERDICTS_CSV) -> str:
    """The figures' verdicts as a small coloured table, with the rule that derives them in one line."""
    from stickslip.claims.verdicts import VERDICT_RULE

    frame = figure_verdicts(figures, csv_path)
    coloured = [c for c in frame.columns if c.startswith(("verdict", "as printed", "best of"))]
    table = frame.style.map(_verdict_colour, subset=coloured).hide(axis="index").to_html()
    rule = "; ".join(f"<i>{v}</i>: {html.escape(r)}" for v, r in VERDICT_RULE.items())
    return (
        f"<h3>Verdicts</h3>{table}<p style='font-size: 0.85em'>k of n: k of the n decided claims reproduced,"
        " counting only rows that could have failed (evidence). Each figure is judged first in the primary"
        " reading, declared in docs/READINGS.md before any result; beside it the equations as printed; the"
        f" best of all readings is a search over them, not a verdict. {rule}. The same verdicts head each"
        f" figure's card on the replication page, <code>{page()}</code>.</p>"
    )


def verdicts(figures, csv_path=VERDICTS_CSV):
    """Display object of ``verdicts_html`` for a notebook cell."""
    from IPython.display import HTML

    return HTML(verdicts_html(figures, csv_path))


# -- rendering ---------------------------------------------------------------------------------------------


def parameters_cell(params: dict):
    """The cell that sets ``PARAMS`` in the kernel, tagged so the renderer never shows it."""
    import nbformat

    cell = nbformat.v4.new_code_cell(f"import json\nPARAMS = json.loads({json.dumps(params)!r})")
    cell.metadata["tags"] = [PARAMETERS_TAG]
    return cell


def code_details(source: str) -> str:
    """A cell's code as a collapsed, syntax-highlighted ``<details>`` block."""
    from pygments import highlight
    from pygments.formatters import HtmlFormatter
    from pygments.lexers import PythonLexer

    code = highlight(source, PythonLexer(), HtmlFormatter(cssclass="highlight"))
    summary = f"<summary style='{SUMMARY_STYLE}; color: #777; font-size: 0.85em'>code</summary>"
    return f'<details class="nb-code">{summary}{code}</details>'


def reader_notebook(nb, source_link: str | None = None):
    """A copy of an executed notebook as a reader sees it: without the parameters cell, each code cell's
    source in a collapsed block above its outputs. ``source_link`` (a relative URL) is linked at the top."""
    import copy

    import nbformat

    out = copy.deepcopy(nb)
    out.cells = [c for c in out.cells if PARAMETERS_TAG not in c.metadata.get("tags", [])]
    for cell in out.cells:
        if cell.cell_type == "code" and cell.source.strip():
            block = nbformat.v4.new_output("display_data", data={"text/html": code_details(cell.source)})
            cell.outputs.insert(0, block)
    if source_link:
        note = (
            f"<small>Rendered from [`{Path(source_link).name}`]({source_link}); the code of each result is "
            "under *code* above it.</small>"
        )
        top = nbformat.v4.new_markdown_cell(note)
        first_md = next((i for i, c in enumerate(out.cells) if c.cell_type == "markdown"), -1)
        out.cells.insert(first_md + 1, top)
    return out


def notebook_title(nb) -> str:
    """The text of the notebook's first level-1 markdown heading (``""`` if it has none)."""
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("# "):
                    return line[2:].strip()
    return ""


#: Page style added to every rendered notebook: a table wider than the page scrolls inside its output instead
#: of being cut at the page's edge.
READER_CSS = """<style>
div.output_subarea, div.output_html, div.output_area details { max-width: 100%; overflow-x: auto; }
div.output_subarea { flex: 1 1 auto; }
</style>
"""


def to_html(nb, source_link: str | None = None, title: str = "") -> str:
    """HTML of an executed notebook for a reader (see ``reader_notebook``), wide tables scrolling."""
    from nbconvert import HTMLExporter

    exporter = HTMLExporter(template_name="classic")
    exporter.exclude_input = exporter.exclude_input_prompt = exporter.exclude_output_prompt = True
    body, _ = exporter.from_notebook_node(
        reader_notebook(nb, source_link), resources={"metadata": {"name": title}}
    )
    return body.replace("</head>", READER_CSS + "</head>", 1)


def render(source: Path, target: Path, params: dict | None = None, timeout: int = 600) -> None:
    """Execute a jupytext notebook (kernel working directory: the current one) and write its reader's HTML
    atomically to ``target`` and the executed notebook, parameters included, next to it (``.ipynb``).

    ``params`` are set as ``PARAMS`` in a tagged cell before the first code cell (papermill-style); the
    HTML never shows that cell. Raises ``nbclient.exceptions.CellExecutionError`` if a cell fails."""
    import jupytext
    import nbformat
    from nbclient import NotebookClient

    from stickslip.io.text_files import write_text_atomic

    source, target = Path(source), Path(target)
    nb = jupytext.read(source)
    if params is not None:
        first_code = next(i for i, c in enumerate(nb.cells) if c.cell_type == "code")
        nb.cells.insert(first_code, parameters_cell(params))
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    NotebookClient(
        nb,
        timeout=timeout,
        kernel_name="python3",
        resources={"metadata": {"path": os.getcwd()}},
        shutdown_kernel="immediate",  # the executed notebook is complete; a graceful stop waits ~1 s
    ).execute()
    link = os.path.relpath(source.resolve(), target.resolve().parent)
    write_text_atomic(target, to_html(nb, link, title=notebook_title(nb) or source.stem))
    nbformat.write(nb, target.with_suffix(".ipynb"))


def render_all(jobs, workers: int = 2, timeout: int = 600) -> list[str]:
    """Render several notebooks in one process, ``workers`` kernels at a time; returns the names of those
    that failed (empty: all rendered).

    ``jobs``: ``(source, target, params, log)`` tuples. One parent for all saves each notebook a Python
    start and the nbclient/nbconvert imports (~2 s a notebook); every notebook still gets a fresh kernel.
    A failing notebook's traceback goes to its ``log`` (the others' logs say where their HTML is), and the
    others are rendered regardless, so one run shows every failure."""
    import traceback
    from concurrent.futures import ThreadPoolExecutor

    def one(job) -> str | None:
        source, target, params, log = job
        try:
            render(Path(source), Path(target), params, timeout=timeout)
        except Exception:  # noqa: BLE001 - reported in the notebook's log, raised as a failed name
            Path(log).write_text(f"{source}: rendering failed\n{traceback.format_exc()}")
            return str(source)
        Path(log).write_text(f"{source} -> {target}\n")
        return None

    with ThreadPoolExecutor(max_workers=max(1, int(workers))) as pool:
        return [name for name in pool.map(one, list(jobs)) if name is not None]
