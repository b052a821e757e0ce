# The replication page: results/index.html, one card per figure of the paper with its verdict and evidence.
# Written after every other result (its input is every final target but the timing table).
import os

import yaml

from stickslip.io.report import paper_figures

PAGE = "results/index.html"
PAGE_FILES = sorted(
    str(p.relative_to(workflow.basedir))
    for p in Path(workflow.basedir, "src", "stickslip", "presentation").rglob("*")
    if p.suffix in (".py", ".j2", ".css", ".yaml")
)


def _relative(path):
    return os.path.relpath(os.path.normpath(path), workflow.basedir)


def page_sources():
    """Every image a rule writes under results/figures/ that shows a paper figure: the 1-DOF figures by their
    config title, the FE scenes by workflow/report/figures.yaml, any other by its rule's docstring."""
    fe_figures = yaml.safe_load(open(Path(workflow.basedir, "workflow", "report", "figures.yaml")))["fe"]
    titled = {**ONEDOF["figures"], **ONEDOF.get("sweep_figures", {})}
    sources = []
    for rule in workflow.rules:
        for output in rule.output:
            m = re.fullmatch(r"results/figures/([^/{}]+)/([^/{}]+)\.png", str(output))
            if not m:
                continue
            folder, label = m[1], m[2]
            if folder in titled:
                figures = paper_figures(titled[folder].get("title", folder))
            elif folder == "fe":
                figures = paper_figures(fe_figures.get(label, {}).get("figures", ""))
            else:
                figures = paper_figures(rule.docstring or "")
            if figures:
                script = Path(rule.snakefile).parent / rule.script if rule.script else None
                sources.append(
                    {
                        "path": str(output),
                        "figures": sorted(figures),
                        "label": label,
                        "rule": rule.name,
                        "rule_file": _relative(rule.snakefile),
                        "script": _relative(script) if script else "",
                    }
                )
    return sorted(sources, key=lambda s: s["path"])


PAGE_SOURCES = page_sources()


def page_inputs(wildcards):
    """Every final target but the page and the timing table, so the page is the last result written."""
    targets = [t for t in ALL_TARGETS if t != PAGE and not t.startswith("results/benchmarks/")]
    return list(dict.fromkeys(targets + [s["path"] for s in PAGE_SOURCES]))


rule replication_page:
    """The replication at a glance: every paper figure's verdict, its claims and links to its evidence."""
    input:
        results=page_inputs,
        code=PAGE_FILES,
    output:
        html=PAGE,
        thumbs=directory("results/page/thumbs"),
    log:
        "results/logs/replication_page/all.log",
    benchmark:
        "results/benchmarks/replication_page/all.tsv"
    conda:
        CONDA_ENV
    params:
        sources=PAGE_SOURCES,
        notebooks=list(config["notebooks"]),
        inverse_figures={k: v["claims"] for k, v in config["inverse"]["figures"].items()},
        fe_default_reading=FE_DEFAULT_READING,
        friction_table=FE_FRICTION,
    script:
        "../scripts/build_page.py"


ALL_TARGETS.append(PAGE)
