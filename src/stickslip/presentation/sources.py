"""Which of the pipeline's images show which figure of the paper, found from the workflow's own rules.

Called by ``workflow/rules/page.smk`` at parse time with Snakemake's rules: every rule output
``results/figures/<folder>/<name>.png`` shows the paper figures named by the config title of its 1-DOF or
sweep figure (``<folder>``), by ``workflow/report/figures.yaml`` for the beam-on-disc scenes
(``results/figures/fe/<scene>.png``), or else by its rule's docstring ("Fig. 4: ...").
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from .report import paper_figures

_FIGURE_PNG = re.compile(r"results/figures/([^/{}]+)/([^/{}]+)\.png")


def figure_numbers(
    folder: str, name: str, titled: dict, fe_figures: dict, docstring: str | None
) -> list[int]:
    """The paper figures an image ``results/figures/<folder>/<name>.png`` shows (sorted; [] for none)."""
    if folder in titled:
        return sorted(paper_figures(titled[folder].get("title", folder)))
    if folder == "fe":
        return sorted(paper_figures((fe_figures.get(name) or {}).get("figures", "")))
    return sorted(paper_figures(docstring or ""))


def page_sources(rules, titled: dict, fe_figures: dict, basedir) -> list[dict]:
    """One entry per image a rule writes that shows a paper figure: its path, figures, label (reading or
    scene), rule name, rules file and script (relative to ``basedir``). ``rules``: objects with ``name``,
    ``output``, ``docstring``, ``snakefile`` and ``script`` (Snakemake's rules)."""

    def relative(path) -> str:
        return os.path.relpath(os.path.normpath(path), basedir)

    sources = []
    for rule in rules:
        for output in rule.output:
            m = _FIGURE_PNG.fullmatch(str(output))
            if not m:
                continue
            figures = figure_numbers(m[1], m[2], titled, fe_figures, rule.docstring)
            if not figures:
                continue
            script = Path(rule.snakefile).parent / rule.script if rule.script else None
            sources.append(
                {
                    "path": str(output),
                    "figures": figures,
                    "label": m[2],
                    "rule": rule.name,
                    "rule_file": relative(rule.snakefile),
                    "script": relative(script) if script else "",
                }
            )
    return sorted(sources, key=lambda s: s["path"])
