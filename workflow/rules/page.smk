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


rule figure_verdicts:
    """Every paper figure's verdict under the primary reading, as printed and in the best of its readings (a
    search): the one table the page and the notebooks read."""
    input:
        deviations="results/claims/deviations.csv",
        fe_readings="results/fe/readings_claims.csv",
        claims=CLAIM_FILES,
        paper="src/stickslip/presentation/paper.yaml",
    output:
        "results/claims/figure_verdicts.csv",
    log:
        "results/logs/figure_verdicts/all.log",
    benchmark:
        "results/benchmarks/figure_verdicts/all.tsv"
    conda:
        CONDA_ENV
    params:
        primary=config["claims"]["primary_reading"],
        printed=config["claims"]["as_printed_reading"],
        fe_primary=FE_DEFAULT_READING,
    script:
        "../scripts/figure_verdicts.py"


ALL_TARGETS.append("results/claims/figure_verdicts.csv")


rule replication_page:
    """The replication at a glance: every paper figure's verdict, its claims and links to its evidence."""
    input:
        # every final target but the page and the timing table (evaluated once every rules file is read)
        verdicts="results/claims/figure_verdicts.csv",
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
        # each linked dataset's `stickslip show` text and each linked source file with line anchors (#L<n>)
        previews=directory("results/page/datasets"),
        source_pages=directory("results/page/source"),
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
        reading_descriptions={
            name: spec.get("description", "")
            for name, spec in {**ONEDOF["readings"], **FE["readings"]}.items()
            if name in config["claims"]["readings"] or name in FE_READINGS
        },
        friction_table=FE_FRICTION,
    script:
        "../scripts/build_page.py"


ALL_TARGETS.append(PAGE)
