# The replication page: results/index.html, one card per figure of the paper with its verdict and evidence.
# Written after every other result (its input is every final target but the timing table).
import yaml

from stickslip.presentation.sources import page_sources

PAGE = "results/index.html"
PAGE_FILES = sorted(
    str(p.relative_to(workflow.basedir))
    for p in Path(workflow.basedir, "src", "stickslip", "presentation").rglob("*")
    if p.suffix in (".py", ".j2", ".css", ".yaml")
)
#: Every image that shows a paper figure, with the rule that draws it (stickslip.presentation.sources).
PAGE_SOURCES = page_sources(
    workflow.rules,
    titled={**ONEDOF["figures"], **ONEDOF.get("sweep_figures", {})},
    fe_figures=yaml.safe_load(open(Path(workflow.basedir, "workflow", "report", "figures.yaml")))["fe"],
    basedir=workflow.basedir,
)


rule replication_page:
    """The replication at a glance: every paper figure's verdict, its claims and links to its evidence."""
    input:
        # every final target but the page and the timing table (evaluated once every rules file is read)
        results=lambda wc: list(
            dict.fromkeys(
                [t for t in ALL_TARGETS if t != PAGE and not t.startswith("results/benchmarks/")]
                + [s["path"] for s in PAGE_SOURCES]
            )
        ),
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
    threads: 2  # thumbnails two at a time (the last job: both cores are free)
    params:
        sources=PAGE_SOURCES,
        notebooks=list(config["notebooks"]),
        inverse_figures={k: v["claims"] for k, v in config["inverse"]["figures"].items()},
        fe_default_reading=FE_DEFAULT_READING,
        friction_table=FE_FRICTION,
    script:
        "../scripts/build_page.py"


ALL_TARGETS.append(PAGE)
