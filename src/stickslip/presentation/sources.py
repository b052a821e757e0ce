"""Which of the pipeline's images show which figure of the paper, found from the workflow's own rules.

Called by ``workflow/rules/page.smk`` at parse time with Snakemake's rules: an image shows the paper figures
its catalogue entry carries (``Entry.figures``, from the config's ``paper_figures`` maps of both halves), or,
drawn by a rule no map names (an equation's curve), those its rule's docstring names ("Fig. 4: ...").

Also the line a source link names: a rule's definition in its rules file, a function's ``def`` in a module
(the page links the repository file and states that line).
"""

from __future__ import annotations

import ast
import os
import re
from pathlib import Path

from .report import paper_figures


def page_sources(rules, basedir, catalogue: dict) -> list[dict]:
    """One entry per image a rule writes that shows a paper figure: its path, figures, label (reading or
    scene), rule name, rules file and script (relative to ``basedir``). ``rules``: objects with ``name``,
    ``output``, ``docstring``, ``snakefile`` and ``script`` (Snakemake's rules); ``catalogue``: path -> Entry
    (stickslip.catalogue), where an image's group and name are looked up, never parsed from its path."""

    def relative(path) -> str:
        return os.path.relpath(os.path.normpath(path), basedir)

    sources = []
    for rule in rules:
        mapped = any(getattr(catalogue.get(str(o)), "figures", ()) for o in rule.output)
        for output in rule.output:
            entry = catalogue.get(str(output))
            if entry is None or entry.kind != "figure":
                continue
            label = entry.name("name")
            # its entry's figures; for a rule the config's maps name nothing of (an equation's curve), its
            # docstring's; an image a mapped rule draws beside its mapped ones (a convergence study): none
            figures = (
                list(entry.figures)
                if entry.figures or mapped
                else sorted(paper_figures(rule.docstring or ""))
            )
            if not figures:
                continue
            script = Path(rule.snakefile).parent / rule.script if rule.script else None
            sources.append(
                {
                    "path": str(output),
                    "figures": figures,
                    "label": label,
                    "rule": rule.name,
                    "rule_file": relative(rule.snakefile),
                    "script": relative(script) if script else "",
                }
            )
    return sorted(sources, key=lambda s: s["path"])


# -- line anchors: which line of a source file a link on the page points to ----------------------------------


def definition_lines(source: str) -> dict[str, int]:
    """Top-level function and class names of Python ``source`` -> the line of their ``def``/``class`` (not
    of a decorator above it)."""
    tree = ast.parse(source)
    kinds = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)
    return {node.name: node.lineno for node in tree.body if isinstance(node, kinds)}


def imported_names(script: str, package: str = "stickslip") -> dict[str, list[str]]:
    """``from <package>.x import a, b`` statements of Python ``script``: module -> the names it imports, in
    the order they appear."""
    out: dict[str, list[str]] = {}
    for node in ast.walk(ast.parse(script)):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if node.module == package or node.module.startswith(package + "."):
                names = out.setdefault(node.module, [])
                names.extend(a.name for a in node.names if a.name not in names)
    return out


def _name_pattern(expression: str) -> re.Pattern | None:
    """A rule's ``name:`` value (a string or an f-string) as a pattern its generated names match."""
    m = re.fullmatch(r"""f?(["'])(.*)\1""", expression.strip())
    if not m:
        return None
    parts = re.split(r"\{[^{}]*\}", m[2])
    return re.compile(".+".join(re.escape(p) for p in parts))


def rule_line(smk: str, rule: str) -> int | None:
    """The line of ``rules file`` text ``smk`` that defines ``rule``: ``rule <name>:``, or the ``rule:`` of a
    rule made in a loop whose ``name:`` (an f-string) makes that name. None when neither is found."""
    lines = smk.splitlines()
    for i, line in enumerate(lines, 1):
        if re.match(rf"\s*(?:rule|checkpoint)\s+{re.escape(rule)}\s*:", line):
            return i
    for i, line in enumerate(lines, 1):
        if not re.fullmatch(r"\s*(?:rule|checkpoint)\s*:\s*", line):
            continue
        for j in range(i, min(i + 12, len(lines))):  # the name sits under the rule's docstring
            m = re.match(r"\s*name\s*:\s*(.*)$", lines[j])
            if m:
                value = m[1] or (lines[j + 1] if j + 1 < len(lines) else "")
                pattern = _name_pattern(value)
                if pattern and pattern.fullmatch(rule):
                    return i
                break
    return None
