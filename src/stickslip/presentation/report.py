"""Captions for ``snakemake --report``: which paper figure each image shows, and its claim statuses.

Snakemake renders one caption file per rule as a Jinja template (with ``snakemake.output`` etc. in scope).
The pipeline's rule ``report_captions`` writes one such file, ``results/report/captions.rst``, that picks
the caption of the job being rendered by its first output path; every figure rule points its ``report()``
caption at that file. The caption text is built here from the deviations table, so the report always shows
the statuses the same run measured.
"""

from __future__ import annotations

import re
from collections import Counter

from ..claims.rows import STATUSES
from ..io.benchmarks import as_number

_FIG = re.compile(r"Fig(?:ure)?s?\.?\s*((?:\d+\s*(?:[-/,]|and|vs\.?|–)?\s*(?:Fig\.?\s*)?)+)", re.IGNORECASE)


def paper_figures(text: str) -> set[int]:
    """Figure numbers a claim's ``figure`` field names: ``Fig. 2-3`` -> {2, 3}, ``Fig. 21/24`` -> {21, 24}."""
    out: set[int] = set()
    for match in _FIG.finditer(str(text)):
        span = match.group(1)
        for a, b in re.findall(r"(\d+)\s*[-–]\s*(\d+)", span):
            lo, hi = int(a), int(b)
            if 0 < hi - lo < 30:
                out.update(range(lo, hi + 1))
        out.update(int(n) for n in re.findall(r"\d+", span))
    return out


def claims_for(rows: list[dict], figures: set[int], reading: str | None = None) -> list[dict]:
    """Deviations-table rows about any of ``figures`` (and, if given, this reading or no reading)."""
    return [
        r
        for r in rows
        if paper_figures(r["figure"]) & figures and (reading is None or r["reading"] in ("", reading))
    ]


def _rst_escape(text: str) -> str:
    return re.sub(r"([*`|_\\])", r"\\\1", str(text))


INDISTINGUISHABLE_NOTE = (
    "Indistinguishable: the measurement lies within 3x its perturbation-ensemble spread of the claim's "
    "threshold, so the pipeline's own numerical noise could decide it; it is called neither reproduced nor "
    "deviating."
)


def _margin(row: dict) -> str:
    """`` (margin M, spread S)`` of a row that has them (the deviations table's columns), else ``""`` (also
    when the row's reason already states them)."""
    margin, spread = as_number(row.get("margin")), as_number(row.get("spread"))
    if margin != margin or "margin" in str(row.get("reason", "")):  # NaN/missing: no threshold decided it
        return ""
    return f" (margin {margin:.3g}" + (f", spread {spread:.3g})" if spread == spread else ", no ensemble)")


def caption_text(title: str, figures: set[int], rows: list[dict], note: str = "") -> str:
    """reStructuredText: the title, the paper figures, the count of every status (zeros included) and one
    line per claim with its margin to the threshold and its ensemble spread."""
    figs = (
        ", ".join(f"Fig. {n}" for n in sorted(figures))
        or "no figure of the paper (added by this replication)"
    )
    lines = [f"**{_rst_escape(title)}**", "", f"Shows: {figs}.", ""]
    if note:
        lines += [_rst_escape(note), ""]
    if not rows:
        lines += ["Claims: none of the claims table refers to this figure.", ""]
        return "\n".join(lines)
    counts = Counter(r["status"] for r in rows)
    failed = sum("solver failed" in r.get("reason", "") for r in rows)
    summary = ", ".join(f"{counts[s]} {s}" for s in STATUSES)
    lines += [f"Claims: {summary}" + (f" ({failed} on a failed solver run)" if failed else "") + ".", ""]
    if counts["indistinguishable"]:
        lines += [INDISTINGUISHABLE_NOTE, ""]
    for r in rows:
        reading = f" [{r['reading']}]" if r["reading"] else ""
        changed = "" if str(r.get("matches_expected")) == "True" else f" (pinned {r['expected']})"
        reason = f" — {_rst_escape(r['reason'])}" if r.get("reason") else ""
        lines.append(f"- ``{r['claim']}``{reading}: **{r['status']}**{changed}{_margin(r)}{reason}")
    return "\n".join(lines) + "\n"


def caption_template(captions: dict[str, str]) -> str:
    """One Jinja template holding every caption, chosen by the rendered job's first output path."""
    parts = ["{% set out = snakemake.output[0] %}"]
    for i, (output, text) in enumerate(sorted(captions.items())):
        keyword = "if" if i == 0 else "elif"
        parts += [f"{{% {keyword} out == {output!r} %}}", "{% raw %}", text.rstrip("\n"), "{% endraw %}"]
    parts += [
        "{% else %}" if captions else "{% if true %}",
        "No caption recorded for this output.",
        "{% endif %}",
    ]
    return "\n".join(parts) + "\n"
