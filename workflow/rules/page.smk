# The replication page (stickslip.catalogue.page()), one card per figure of the paper with its verdict and evidence.
# Written after every other result (its input is every final target but the timing table).

from stickslip.presentation.sources import page_sources

PAGE = paths.page()
PAGE_FILES = sorted(
    str(p.relative_to(workflow.basedir))
    for p in Path(workflow.basedir, "src", "stickslip", "presentation").rglob("*")
    if p.suffix in (".py", ".j2", ".css", ".yaml")
)
#: Every image that shows a paper figure, with the rule that draws it (stickslip.presentation.sources).
PAGE_SOURCES = page_sources(workflow.rules, basedir=workflow.basedir, catalogue=CATALOGUE)


rule figure_verdicts:
    """Every paper figure's verdict under the primary reading, as printed and in the best of its readings (a
    search): the one table the page and the notebooks read."""
    input:
        deviations=paths.claims_table(),
        fe_readings=paths.fe_readings_claims(),
        claims=CLAIM_FILES,
        paper="src/stickslip/presentation/paper.yaml",
    output:
        **outputs("figure_verdicts"),
    log:
        paths.log("figure_verdicts", "all"),
    benchmark:
        paths.benchmark("figure_verdicts", "all")
    conda:
        CONDA_ENV
    params:
        claims=CLAIMS,  # the claim rows as the parse read them (common.smk): no job reads the files again
        primary=CFG.claims.primary_reading,
        printed=CFG.claims.as_printed_reading,
        alternative=CFG.claims.alternative_reading or "",
        fe_primary=FE_DEFAULT_READING,
    script:
        "../scripts/figure_verdicts.py"


ALL_TARGETS.append(paths.figure_verdicts())


rule replication_page:
    """The replication at a glance: every paper figure's verdict, its claims and links to its evidence."""
    input:
        # every final target but the page and the timing table (evaluated once every rules file is read)
        verdicts=paths.figure_verdicts(),
        results=lambda wc: list(
            dict.fromkeys(
                [t for t in ALL_TARGETS if t != PAGE and not paths.is_benchmark(t)]
                + [s["path"] for s in PAGE_SOURCES]
            )
        ),
        code=PAGE_FILES,
    output:
        # thumbnails and each linked dataset's `stickslip show` text: folders
        **outputs("replication_page", flags=dict.fromkeys(("thumbs", "previews"), directory)),
    log:
        paths.log("replication_page", "all"),
    benchmark:
        paths.benchmark("replication_page", "all")
    conda:
        CONDA_ENV
    threads: 2  # thumbnails two at a time (the last job: both cores are free)
    params:
        claims=CLAIMS,
        sources=PAGE_SOURCES,
        notebooks=list(CFG.notebooks),
        inverse_figures={k: v.claims for k, v in CFG.inverse.figures.items()},
        fe_default_reading=FE_DEFAULT_READING,
        reading_descriptions={
            name: spec.description or ""
            for name, spec in {**CFG.onedof.readings, **CFG.fe.readings}.items()
            if name in CFG.claims.readings or name in CFG.fe.readings
        },
        friction_table=FE_FRICTION,
        configuration=results_owner.describe(CONFIG_OVERLAYS),
    script:
        "../scripts/build_page.py"


ALL_TARGETS.append(PAGE)
