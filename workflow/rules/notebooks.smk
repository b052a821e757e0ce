# Rendered comparison notebooks (jupytext percent files in notebooks/, executed here, HTML in results/).
NOTEBOOKS = list(CFG.notebooks)


rule render_notebooks:
    """Every notebook in one job, two kernels at a time: they all wait for the claims table anyway, and one
    parent process instead of one per notebook saves ~2 s of start-up each."""
    input:
        notebooks=expand("notebooks/{name}.py", name=NOTEBOOKS),
        data=list(dict.fromkeys(f for name in NOTEBOOKS for f in notebook_inputs(name))),
    output:
        **outputs("render_notebooks", flags={"notebooks": report_of("Notebooks", "notebook")}),
    log:
        [paths.log("render_notebooks", name) for name in NOTEBOOKS],
    benchmark:
        paths.benchmark("render_notebooks", "all")
    conda:
        CONDA_ENV
    threads: 2
    params:
        nb_params={name: notebook_params(name) for name in NOTEBOOKS},
    script:
        "../scripts/render_notebooks.py"


ALL_TARGETS.extend(products_of("render_notebooks"))
