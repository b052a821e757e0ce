"""The replication at a glance: ``results/index.html``, one card per figure of the paper.

Everything on the page is read from the run: the claims table (``results/claims/deviations.csv``), the
claims files (which paper figures each claim is about), the reading ranking, the FE readings table, the
inverse study's tables, the images the figure rules wrote and the rendered notebooks. The paper's figure
list and captions ship with this package (``paper.yaml``). The page is static: CSS inline, no script, no
network; every link is relative, so it opens from the file system.

Beside it, under ``results/page/``: ``datasets/<path>.html``, each linked dataset's ``stickslip show`` text (a
netCDF file has no preview in a browser). A link to a rule or a function opens its file in the repository and
names the line of its definition (``workflow/rules/fe.smk, line 253``).
"""

from __future__ import annotations

import functools
import html
import math
import os
import re
from collections import Counter
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

import yaml

from .. import catalogue as paths
from ..claims.load import DISC_SPEEDS, load_claims
from ..claims.rows import EVIDENCE_CLASSES, Claim
from ..claims.table import read_table
from ..claims.verdicts import (
    SPEED_COLUMNS,
    VERDICT_RULE,
    VERDICTS,
    is_evidence,
    readings_by_preference,
    rows_in_reading,
    speed_of,
    status_counts,
    tally,
    verdict_label,
)
from ..io.benchmarks import as_number
from ..io.text_files import write_text_atomic
from ..pipeline.code_deps import module_file
from .report import paper_figures
from .show import show_text
from .sources import definition_lines, imported_names, rule_line

#: The quantities a card's headline table shows first (the paper's amplitude, frequency, stick and slip).
HEADLINE_ORDER = ("amplitude", "displacement", "frequency", "stick", "slip", "velocity", "speed")

HERE = Path(__file__).parent
THUMB_WIDTH = 360  # px: the thumbnails' width (the cards show them at up to 320 px)


def image_rank(source, reading: str, preferred: list[str], datasets: list[str]) -> tuple:
    """Sort key of the images of one paper figure: the best reading's first, then an image of that figure
    alone (a beam-on-disc ``figNN`` before the scene overviews that show several figures), then by reading
    preference, then the scene its claims read most."""
    rank = preferred.index(source.label) if source.label in preferred else len(preferred)
    read = -sum(source.label in p for p in datasets)
    return (source.label != reading, len(source.figures) > 1, rank, read, source.label)


@dataclass
class Source:
    """An image (or table) a rule wrote that shows some figures of the paper."""

    path: str  #: relative to the working directory, e.g. results/figures/fig02/consistent_caption.png
    figures: list[int]
    label: str  #: the reading or scene it shows
    rule: str
    rule_file: str = ""  #: relative to the working directory
    script: str = ""


def paper_spec(path: Path | None = None) -> dict:
    """The paper's figure list and captions (``paper.yaml``)."""
    return yaml.safe_load((path or HERE / "paper.yaml").read_text())


def not_comparable_causes(rows: list[dict]) -> dict[str, int]:
    """How many not-comparable rows each cause has (the claims table's ``cause``), most frequent first."""
    from ..claims.evaluate import NOT_COMPARABLE_CAUSES

    causes = Counter(r.get("cause", "") for r in rows if r["status"] == "not-comparable")
    return {NOT_COMPARABLE_CAUSES.get(k, k or "no cause recorded"): v for k, v in causes.most_common()}


def read_csv(path) -> list[dict]:
    """A table's rows; none when the run has not written it."""
    return read_table(path) if Path(path).is_file() else []


def source_modules(script: Path, src: Path) -> list[tuple[Path, list[tuple[str, int]]]]:
    """The project modules a script imports from (``from stickslip.x import a``), as files under ``src``, each
    with the (name, line of its ``def``/``class``) of the functions and classes it takes from them (a
    constant or a re-exported name has no line of its own there and is left out)."""
    if not script.is_file():
        return []
    found = []
    for module, names in imported_names(script.read_text()).items():
        path = module_file(src.resolve(), module)
        if path is None:
            continue
        lines = definition_lines(path.read_text())
        found.append((src / path.relative_to(src.resolve()), [(n, lines[n]) for n in names if n in lines]))
    return found


_HEADING = re.compile(r"<h([1-4])[^>]*\bid=\"([^\"]+)\"[^>]*>(.*?)</h\1>", re.S)


def notebook_sections(path: Path) -> list[tuple[str, str, set[int], int]]:
    """(anchor, heading text, paper figures it names, heading level) of every heading of a rendered
    notebook."""
    if not path.is_file():
        return []
    out = []
    for level, anchor, inner in _HEADING.findall(path.read_text(errors="replace")):
        text = html.unescape(re.sub(r"<[^>]+>", "", inner)).replace("¶", "").strip()
        out.append((anchor, text, paper_figures(text), int(level)))
    return out


def notebook_link(number: int, notebooks: dict[str, list]) -> tuple[str, str] | None:
    """(notebook name, anchor) of the most specific notebook heading naming figure ``number``: the one
    naming fewest figures, then the section rather than the notebook's title."""
    best = None
    for name, sections in notebooks.items():
        for anchor, _text, figs, level in sections:
            key = (len(figs), level == 1)
            if number in figs and (best is None or key < best[0]):
                best = (key, name, anchor)
    return (best[1], best[2]) if best else None


def fmt(value) -> str:
    """A table number for display: 4 significant digits, blank for NaN."""
    x = as_number(value)
    if x != x:
        return "" if value in ("", None, "nan", "NaN") else str(value)
    return f"{x:.4g}"


def percent(value) -> str:
    """A relative deviation for display: ``+12 %``, blank for NaN."""
    x = as_number(value)
    return f"{100 * x:+.0f} %" if x == x else ""


def thumbnail(png: Path, out: Path, width: int = THUMB_WIDTH) -> Path:
    """A small copy of ``png`` (kept when it is newer than the image)."""
    from PIL import Image

    if out.is_file() and out.stat().st_mtime >= png.stat().st_mtime:
        return out
    out.parent.mkdir(parents=True, exist_ok=True)
    with Image.open(png) as im:
        im = im.convert("RGB")
        height = max(1, round(im.height * width / im.width))
        im.resize((width, height), Image.LANCZOS, reducing_gap=2.0).save(out, compress_level=6)
    return out


def svg_plot(xs, ys, xlabel: str, ylabel: str, width: int = THUMB_WIDTH, height: int = 240) -> str:
    """A small line plot as SVG text (for a curve the pipeline tabulates but does not draw): the points, a
    frame and the range of each axis."""
    left, right, top, bottom = 46, 10, 10, 36
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    sx = (width - left - right) / ((x1 - x0) or 1.0)
    sy = (height - top - bottom) / ((y1 - y0) or 1.0)
    points = " ".join(
        f"{left + (x - x0) * sx:.1f},{height - bottom - (y - y0) * sy:.1f}" for x, y in zip(xs, ys)
    )
    esc = html.escape
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">'
        f'<rect width="{width}" height="{height}" fill="white"/>'
        f'<rect x="{left}" y="{top}" width="{width - left - right}" height="{height - top - bottom}" '
        'fill="none" stroke="#888"/>'
        f'<polyline points="{points}" fill="none" stroke="#1f77b4" stroke-width="1.5"/>'
        f'<text x="{left}" y="{height - bottom + 13}">{x0:.3g}</text>'
        f'<text x="{width - right}" y="{height - bottom + 13}" text-anchor="end">{x1:.3g}</text>'
        f'<text x="{(width + left) / 2}" y="{height - 6}" text-anchor="middle">{esc(xlabel)}</text>'
        f'<text x="{left - 4}" y="{height - bottom}" text-anchor="end">{y0:.3g}</text>'
        f'<text x="{left - 4}" y="{top + 9}" text-anchor="end">{y1:.3g}</text>'
        f'<text x="12" y="{(height - bottom + top) / 2}" text-anchor="middle" '
        f'transform="rotate(-90 12 {(height - bottom + top) / 2})">{esc(ylabel)}</text></svg>\n'
    )


def make_thumbnails(jobs, workers: int = 2) -> None:
    """``thumbnail(png, out)`` for every ``(png, out)`` of ``jobs``, ``workers`` at a time (Pillow decodes
    and resizes without holding the interpreter lock)."""
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=workers) as pool:
        list(pool.map(lambda job: thumbnail(*job), jobs))


#: Per-quantity columns of the inverse study's tables, shown as one range_text cell each.
RANGE_PREFIXES = ("best_", "stated_", "lower_", "upper_", "identifiable_", "open_")
KEPT_COLUMNS = ("identifiable_dimensions",)


def range_text(row: dict, quantity: str) -> str:
    """``q = best [lo, hi]`` for an identified quantity, ``q: range lo-hi (open above)`` for one that is not
    (never a point), from an inverse table's best_/lower_/upper_/identifiable_/open_ columns."""
    lo, hi = fmt(row.get(f"lower_{quantity}")), fmt(row.get(f"upper_{quantity}"))
    best = fmt(row.get(f"best_{quantity}"))
    if not (lo or hi or best):
        return ""
    if str(row.get(f"identifiable_{quantity}", "1")) in ("0", "0.0", "False"):
        opened = row.get(f"open_{quantity}") or ""
        return f"{quantity}: range {lo}–{hi}" + (f" (open {opened})" if opened else "")
    return f"{quantity} = {best} [{lo}, {hi}]" if lo or hi else f"{quantity} = {best}"


def inverse_sentence(row: dict, conflicts: list[dict] = ()) -> str:
    """The inverse study's answer for one figure and family, in words: can one parameter set of the family
    give all of the figure's numbers; if not, the smallest set of numbers that cannot hold together; what
    the numbers fix (identified combinations with their ranges) and what they leave open."""
    n = row.get("numbers", "")
    family = row.get("family", "")
    verdict = row.get("verdict", "")
    quantities = [c[len("lower_") :] for c in row if c.startswith("lower_")]
    identified = [q for q in quantities if str(row.get(f"identifiable_{q}")) in ("1", "1.0", "True")]
    fixed = [range_text(row, q) for q in identified]
    if verdict == "consistent":
        head = f"{family} family: one parameter set gives all {n} of the figure's numbers within tolerance"
    elif verdict == "inconsistent" and as_number(row.get("worst_residual")) == math.inf:
        return (
            f"{family} family: no parameter set the fit tried measures all {n} of the figure's numbers "
            f"({row.get('worst_claim', '')} stays unmeasured: the model rests, diverges or never sticks)"
            "."
        )
    elif verdict == "inconsistent":
        smallest = min(conflicts, key=lambda r: int(r.get("size") or 0), default=None)
        if smallest and int(smallest.get("size") or 0) == 1:
            clash = f"; {smallest['claims']} alone cannot be met"
        elif smallest and smallest.get("claims"):
            clash = f"; the smallest set that cannot hold together: {smallest['claims']}"
        else:
            clash = ""
        head = (
            f"{family} family: no parameter set gives all {n} of the figure's numbers (the worst, "
            f"{row.get('worst_claim', '')}, stays {fmt(row.get('worst_residual'))} tolerances off{clash})"
        )
    else:
        head = f"{family} family: {verdict or 'no verdict'}"
    if fixed:
        return f"{head}; the numbers fix {', '.join(fixed)} (the rest range over their bounds)."
    return f"{head}; the numbers fix no parameter combination."


class PageBuilder:
    """Gathers every card's content from a run's results (paths relative to ``workdir``)."""

    def __init__(
        self,
        workdir: Path,
        sources: list[Source],
        notebooks: list[str],
        inverse_figures: dict[str, list[str]],
        fe_default_reading: str = "",
        reading_descriptions: dict[str, str] | None = None,
        friction_table: str = paths.friction_table(),
        claims_glob: str = "config/claims/*.yaml",
        workers: int = 1,
        configuration: str = "config/*.yaml",
        claims: list[Claim] | None = None,
    ):
        self.workdir = Path(workdir)
        self.results = self.workdir / paths.RESULTS
        self.sources = sources
        self.paper = paper_spec()
        #: the claim rows (the pipeline passes those its parse read; otherwise read from ``claims_glob``)
        self.claims = load_claims(sorted(self.workdir.glob(claims_glob))) if claims is None else claims
        #: claim id -> the paper figures it is about (its ``figures``, which every row declares)
        self.figures_of = {c.id: sorted(c.figures) for c in self.claims}
        self.claim = {c.id: c for c in self.claims}
        self.rows = read_table(self.workdir / paths.claims_table())
        #: every figure's verdicts, the table the notebooks read too (stickslip.claims.verdicts)
        self.verdicts = {r["figure"]: r for r in read_csv(self.workdir / paths.figure_verdicts())}
        self.descriptions = dict(reading_descriptions or {})
        self.order = [r["reading"] for r in read_csv(self.workdir / paths.reading_ranking())]
        self.fe_rows = [r for r in read_csv(self.workdir / paths.fe_readings_claims()) if is_evidence(r)]
        self.fe_default = fe_default_reading
        self.friction_table = friction_table
        self.inverse_figures = inverse_figures
        self.inverse_paths = self._inverse_tables()
        self.inverse = {name: read_csv(self.workdir / p) for name, p in self.inverse_paths.items()}
        self.notebooks = {n: notebook_sections(self.workdir / paths.notebook(n)) for n in notebooks}
        self.thumbs = self.workdir / paths.page_thumbs()
        self.thumb_jobs: list[tuple[Path, Path]] = []  #: (image, thumbnail), made by ``context``
        self.previews = self.workdir / paths.page_previews()
        #: dataset -> its text page (its ``stickslip show`` text), for ``context`` to write
        self.text_jobs: dict[Path, Path] = {}
        self.workers = workers
        self.configuration = configuration

    # -- links ----------------------------------------------------------------------------------------

    def href(self, path) -> str | None:
        """A link relative to the page (results/index.html), or None when the file does not exist."""
        full = self.workdir / path  # (an absolute path stays itself)
        if not full.exists():
            return None
        parts = Path(os.path.relpath(full, self.workdir)).parts
        return "/".join(parts[1:]) if parts[0] == self.results.name else "/".join(("..", *parts))

    def page_path(self, path: Path) -> str:
        """The link to a file under the results folder that this page writes (it may not exist yet)."""
        return Path(os.path.relpath(path, self.results)).as_posix()

    def source_link(self, path, line: int | None = None, name: str = "") -> dict:
        """A link to the repository file ``path``; ``line``, where known, is the line of the definition the
        link is about (stated in its text: a browser opens a plain file at its top). ``href`` None when the
        file does not exist."""
        label = name or str(path)
        text = f"{label}, line {line}" if line else label
        return {"href": self.href(path), "text": text, "label": label, "line": line}

    def dataset_link(self, path) -> dict:
        """A dataset's link: for a netCDF file under results/, its text preview (``stickslip show``, a page
        registered for ``context`` to write), beside the file."""
        full, file = self.workdir / path, self.href(path)
        rel = Path(os.path.relpath(full, self.results))
        if not (str(path).endswith(".nc") and full.is_file() and rel.parts[0] != ".."):
            return {"href": file, "text": str(path), "file": None}
        out = self.text_jobs.setdefault(full, self.previews / f"{rel.as_posix()}.html")
        return {"href": self.page_path(out), "text": str(path), "file": file}

    # -- inverse --------------------------------------------------------------------------------------

    def _inverse_tables(self) -> dict[str, str]:
        """Every table of the inverse study with a ``figure`` column (the per-figure verdicts first), by
        file name."""
        tables = sorted(paths.inverse_table(name) for name in paths.INVERSE_TABLES)
        tables.sort(key=lambda p: p != paths.inverse_table("summary"))
        return {Path(p).name: p for p in tables if "figure" in (read_csv(self.workdir / p)[:1] or [{}])[0]}

    def inverse_for(self, number: int) -> list[dict]:
        """The inverse study's rows about paper figure ``number`` (an inverse figure covers the paper figures
        of the claims it is fitted to): one entry per table, its columns and rows."""
        names = [
            name
            for name, ids in self.inverse_figures.items()
            if any(number in self.figures_of.get(i, []) for i in ids)
        ]
        out = []
        conflicts = [r for r in self.inverse.get("conflicts.csv", []) if r.get("figure") in names]
        for table, rows in self.inverse.items():
            mine = [r for r in rows if r.get("figure") in names]
            if not mine:
                continue
            ranged = [c[len("lower_") :] for c in mine[0] if c.startswith("lower_")]
            columns = [c for c in mine[0] if not c.startswith(RANGE_PREFIXES) or c in KEPT_COLUMNS]
            rows = [[fmt(r[c]) if c not in ("figure", "family") else r[c] for c in columns] for r in mine]
            if ranged:  # one readable cell instead of five columns per quantity
                columns.append("values (a point) or ranges (not identifiable)")
                for row, r in zip(rows, mine):
                    row.append("; ".join(filter(None, (range_text(r, q) for q in ranged))))
            out.append(
                {
                    "table": table,
                    "href": self.href(self.inverse_paths[table]),
                    "columns": columns,
                    "rows": rows,
                    "sentences": [
                        inverse_sentence(r, [c for c in conflicts if c["family"] == r["family"]])
                        for r in mine
                        if table == "summary.csv" and r.get("verdict")
                    ],
                }
            )
        return out

    # -- cards ----------------------------------------------------------------------------------------

    def dataset_paths(self, claim_id: str) -> list[str]:
        """Every dataset the claim reads; none for an id in no claims file (a table older than the files)."""
        claim = self.claim.get(claim_id)
        return [] if claim is None else claim.dataset_paths()

    def rows_about(self, number: int | None, section: str | None = None) -> list[dict]:
        if number is None:
            return [
                r
                for r in self.rows
                if not self.figures_of.get(r["claim"])
                and r["claim"] in self.claim
                and self.claim[r["claim"]].section == section
            ]
        return [r for r in self.rows if number in self.figures_of.get(r["claim"], [])]

    def per_reading(self, rows: list[dict], fe: bool) -> list[dict]:
        """The figure's verdict in every reading (FE: every FE reading, in the order of the FE readings table,
        whose rows each name their reading)."""
        if fe:
            ids = {r["claim"] for r in rows}
            rows = [r for r in self.fe_rows if r["claim"] in ids]
        readings = (
            dict.fromkeys(r["reading"] for r in rows) if fe else readings_by_preference(rows, self.order)
        )
        return [{"reading": rd, "verdict": tally(rows_in_reading(rows, rd)).label} for rd in readings]

    def images(self, number: int, reading: str, rows: list[dict]) -> list[dict]:
        """The images showing figure ``number``: the best reading's first, then the scenes its claims read."""
        mine = [s for s in self.sources if number in s.figures and (self.workdir / s.path).is_file()]
        preferred = readings_by_preference(rows, self.order)
        datasets = [p for r in rows for p in self.dataset_paths(r["claim"])]

        out = []
        for s in sorted(mine, key=lambda s: image_rank(s, reading, preferred, datasets)):
            script = self.workdir / s.script if s.script else None
            out.append(
                {
                    "label": s.label,
                    "full": self.href(s.path),
                    "rule": s.rule,
                    "rule_file": self.source_link(s.rule_file, self.rule_line(s)) if s.rule_file else None,
                    "script": self.source_link(s.script) if s.script else None,
                    "modules": [
                        {
                            **self.source_link(m.relative_to(self.workdir)),
                            "names": [self.source_link(m.relative_to(self.workdir), n, f) for f, n in names],
                        }
                        for m, names in source_modules(script, self.workdir / "src")
                    ]
                    if script
                    else [],
                    "path": s.path,
                }
            )
        return out

    def rule_line(self, source: Source) -> int | None:
        path = self.workdir / source.rule_file
        return rule_line(path.read_text(), source.rule) if path.is_file() else None

    def verdict_cells(self, key: str) -> dict:
        """The figure's row of figure_verdicts.csv, each verdict (primary, as printed, the other defensible
        application, the search) as its columns without their prefix (``verdict``, ``reading``,
        ``reproduced`` of ``decided``, ...); None for a verdict the row leaves blank."""
        row = self.verdicts.get(key, {})

        def cell(prefix):
            cell = {k.removeprefix(f"{prefix}_"): v for k, v in row.items() if k.startswith(f"{prefix}_")}
            return cell if cell.get("verdict") else None

        unjudged = {"verdict": "not comparable", "reading": "", "reproduced": 0, "decided": 0}
        return {
            "primary": cell("primary") or {**unjudged, "undecided": 0, "not_comparable": 0},
            **{prefix: cell(prefix) for prefix in ("printed", "alternative", "best")},
            **{column: row.get(column, "") for column in ("readings_searched", "not_evidence")},
            **{column: row.get(column, "") for column in SPEED_COLUMNS.values()},
        }

    def headline(self, rows: list[dict]) -> list[dict]:
        """The paper's numbers for the figure beside this run's (primary reading), amplitude, frequency and
        stick/slip first: every value claim that is evidence, with its deviation in %."""

        def rank(r):
            q = r["quantity"].lower()
            return (
                next((i for i, w in enumerate(HEADLINE_ORDER) if w in q), len(HEADLINE_ORDER)),
                r["claim"],
            )

        values = sorted((r for r in rows if r["kind"] in ("value", "ratio") and is_evidence(r)), key=rank)
        return [{**self.claim_row(r), "deviation": percent(r["deviation"])} for r in values]

    def card(self, entry: dict) -> dict:
        number = entry.get("number")
        fe = entry.get("half") == "fe"
        key = f"fig-{number}" if number is not None else entry["key"]
        everything = self.rows_about(number, entry.get("section"))
        v = self.verdict_cells(str(number) if number is not None else entry["key"])
        primary = v["primary"]["reading"] if not fe else ""
        judged = rows_in_reading(everything, primary) if primary else everything
        evidence = [r for r in judged if is_evidence(r)]
        apart = [r for r in everything if not is_evidence(r)]
        if primary:  # a row set apart is shown once, in the primary reading where it depends on one
            apart = rows_in_reading(apart, primary)
        images = self.images(number, primary or self.fe_default, everything) if number is not None else []
        best = (v["best"] or {}).get("reading", "")
        best_drawn = (
            not best or best == primary or any(im["label"] == best for im in images) or fe or not images
        )
        thumb = None
        if images:
            source = images[0]["path"]  # one thumbnail per image, however many figures it shows
            out = self.thumbs / (Path(source).relative_to(self.results.name).as_posix().replace("/", "__"))
            if (self.workdir / source, out) not in self.thumb_jobs:
                self.thumb_jobs.append((self.workdir / source, out))
            thumb = self.page_path(out)
        table = None
        from_table = entry.get("table") or entry.get("drawn_from_table")
        csv_path = self.workdir / self.friction_table
        if from_table and csv_path.is_file():
            rows_ = read_csv(csv_path)
            if entry.get("table"):
                columns = list(rows_[0]) if rows_ else []
                table = {"columns": columns, "rows": [[fmt(r[c]) for c in columns] for r in rows_]}
            elif not images:
                x, y = list(rows_[0])[:2]
                out = self.thumbs / f"fig{number:02d}.svg"
                out.parent.mkdir(parents=True, exist_ok=True)
                out.write_text(
                    svg_plot([as_number(r[x]) for r in rows_], [as_number(r[y]) for r in rows_], x, y)
                )
                thumb = self.page_path(out)
                images = [{"label": "drawn by this page from the friction table", "full": thumb, "path": ""}]
        data = [self.friction_table] if from_table else []
        for r in judged:
            for p in self.dataset_paths(r["claim"]):
                data.append(p.format(reading=primary) if "{reading}" in p else p)
        datasets = [self.dataset_link(p) for p in dict.fromkeys(data)]
        found = notebook_link(number, self.notebooks)  # none for a text card (no number)
        notebook = found and {"name": found[0], "href": f"{self.href(paths.notebook(found[0]))}#{found[1]}"}
        title = entry.get("title") or (
            f"Fig. {number}" + (" (the μ(v_r) table)" if entry.get("table") else "")
        )
        speeds = [{"label": DISC_SPEEDS[s], "text": v[col]} for s, col in SPEED_COLUMNS.items()] if fe else []
        verdict = v["primary"]["verdict"]
        return {
            "key": key,
            "number": number,
            "title": title,
            "half": entry.get("half", "text"),
            "caption": entry["caption"],
            "verdict": verdict,
            "verdict_class": verdict.replace(" ", "-"),
            "rule": VERDICT_RULE[verdict],
            "v": v,
            "speeds": speeds,
            "best_drawn": best_drawn,
            "n_rows": len(evidence),
            "headline": self.headline(evidence),
            "claims": [self.claim_row(r) for r in evidence],
            "apart": [self.claim_row(r) for r in apart],
            "per_reading": self.per_reading(everything, fe) if everything else [],
            "images": images,
            "thumb": thumb,
            "table": table,
            "datasets": [d for d in datasets if d["href"]],
            "inverse": self.inverse_for(number) if number is not None else [],
            "notebook": notebook,
        }

    def claim_row(self, r: dict) -> dict:
        conclusion, _, rest = r["reason"].partition(" | ")
        claim = self.claim.get(r["claim"])
        return {
            "claim": r["claim"],
            "reading": r["reading"] or "all",
            "speed": DISC_SPEEDS.get(speed_of(claim), ""),
            "quantity": r["quantity"],
            "reported": fmt(r["reported"]),
            "measured": fmt(r["measured"]),
            "unit": r["unit"],
            "margin": fmt(r["margin"]),
            "spread": fmt(r["spread"]),
            "status": r["status"],
            "evidence": r.get("evidence", "evidence"),
            "conclusion": conclusion,
            "details": rest.replace(" | ", "; "),
            "quote": r["quote"],
        }

    # -- summary --------------------------------------------------------------------------------------

    def half_summary(self, half: str, cards: list[dict]) -> dict:
        """Per half and per verdict of figure_verdicts.csv (primary, as printed, the other defensible
        application, the search): how many figures carry each label, the readings, and the claim checks
        behind them (``k`` reproduced of ``n`` decided, evidence only)."""
        mine = [c for c in cards if c["half"] == half]

        def under(prefix: str) -> dict:
            cells = [c["v"][prefix] for c in mine if c["v"][prefix]]
            labels = Counter(cell["verdict"] for cell in cells)
            return {
                "reading": ", ".join(sorted({cell["reading"] for cell in cells} - {""})),
                "k": sum(int(cell["reproduced"] or 0) for cell in cells),
                "n": sum(int(cell["decided"] or 0) for cell in cells),
                "counts": {v: labels[v] for v in VERDICTS},
            }

        return {
            "title": self.paper["halves"][half],
            "figures": len(mine),
            "searched": max((int(c["v"]["readings_searched"] or 0) for c in mine), default=0),
            "cards": mine,
            **{prefix: under(prefix) for prefix in ("primary", "printed", "alternative", "best")},
        }

    def provenance(self) -> dict:
        """What the page is a build of: the paper, the configuration, the code's commit and the build time."""
        from ..io.netcdf import PAPER_REFERENCE, git_revision

        return {
            "paper": PAPER_REFERENCE,
            "configuration": self.configuration,
            "commit": git_revision(self.workdir),
            "built": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
        }

    def glossary(self) -> dict:
        return {
            "readings": self.descriptions,
            "statuses": self.paper["glossary"]["statuses"],
            "verdicts": VERDICT_RULE,
            "evidence": EVIDENCE_CLASSES,
            "terms": self.paper["glossary"]["terms"],
        }

    def context(self) -> dict:
        cards = [self.card(e) for e in self.paper["figures"]] + [self.card(e) for e in self.paper["text"]]
        make_thumbnails(self.thumb_jobs, self.workers)
        self.write_text_pages()
        placed = {r["claim"] for c in cards for r in c["claims"] + c["apart"]} | {
            r["claim"] for r in self.rows if self.figures_of.get(r["claim"])
        }
        unplaced = sorted({r["claim"] for r in self.rows} - placed)
        halves = [self.half_summary(h, cards) for h in self.paper["halves"]]
        evidence = [r for r in self.rows if is_evidence(r)]
        apart = Counter(r.get("evidence", "") for r in self.rows if not is_evidence(r))
        return {
            "provenance": self.provenance(),
            "outcome": outcome_line(halves),
            "cards": cards,
            "halves": halves,
            "verdicts": VERDICTS,
            "verdict_rule": VERDICT_RULE,
            "glossary": self.glossary(),
            "claim_totals": status_counts(r["status"] for r in evidence),
            "not_comparable_causes": not_comparable_causes(evidence),
            "n_claim_rows": len(evidence),
            "n_claims": len({r["claim"] for r in evidence}),
            "apart": {k.replace("_", " "): v for k, v in sorted(apart.items())},
            "unplaced": unplaced,
            "links": {
                "deviations": self.href(paths.claims_table()),
                "deviations_md": self.href(paths.claims_table("md")),
                "verdicts": self.href(paths.figure_verdicts()),
                "ranking": self.href(paths.reading_ranking()),
                "fe_readings": self.href(paths.fe_readings_claims()),
                "interpretation": self.href(paths.notebook("interpretation_study")),
                "inverse": self.href(paths.notebook("inverse_study")),
                "readme": self.href("README.md"),
            },
        }

    def write_text_pages(self) -> None:
        """Every registered dataset's ``stickslip show`` text as a page of its own (escaped), linking back to
        the page and to the file. The folder exists even when empty (it is an output of the page rule)."""
        index = self.workdir / paths.page()
        self.previews.mkdir(parents=True, exist_ok=True)
        for path, out in self.text_jobs.items():
            text = (
                _templates()
                .get_template("text_page.html.j2")
                .render(
                    title=os.path.relpath(path, self.workdir),
                    index_href=relative_href(index, out),
                    file_href=relative_href(path, out),
                    file_label=f"download {path.name}",
                    text=show_text(path),
                )
            )
            write_text_atomic(out, text)


def outcome_line(halves: list[dict]) -> str:
    """One line under the primary reading: per half of the paper, the label the figures' verdicts use
    (:func:`verdict_label`, the glossary's rule) for the checks reproduced of those decided."""
    parts = [
        f"{h['title'].split(' (')[0]}: {verdict_label(h['primary']['k'], h['primary']['n'])} "
        f"({h['primary']['k']} of {h['primary']['n']} decided claim checks reproduced)"
        for h in halves
    ]
    return "Under the primary reading: " + "; ".join(parts) + "."


def relative_href(target: Path, page: Path) -> str:
    """The link from the HTML file ``page`` to ``target``."""
    return Path(os.path.relpath(target, page.parent)).as_posix()


@functools.cache
def _templates():
    import jinja2

    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(HERE / "templates"),
        autoescape=jinja2.select_autoescape(["html", "j2"]),
        trim_blocks=True,
        lstrip_blocks=True,
        undefined=jinja2.StrictUndefined,
    )


def build_page(out: Path, builder: PageBuilder) -> Path:
    """Write the page, its CSS inline, to ``out`` (atomically) and return its path."""
    css = (HERE / "templates" / "page.css").read_text()
    return write_text_atomic(
        out, _templates().get_template("page.html.j2").render(css=css, **builder.context())
    )
