# Beam on rotating rigid disc (paper Sections 8-12, issue 5). Scene names come from config["fe"].
from snakemake.utils import validate

validate(config, "../schemas/fe.schema.yaml")

FE_SCENES = list(config["fe"]["scenes"])
FE_SWEEPS = list(config["fe"]["sweeps"])
FE_FRICTION = config["fe"]["friction_table"]
FE_STUDIES = ["convergence", "stability"]


def check_fe_config(fe_cfg, producible):
    """Resolve every FE scene and reference at parse time, so a bad value fails before any job starts,
    with the config key named (the schema cannot see NaN, unknown scene names or a missing table)."""
    from stickslip.fe.pipeline import scene_mapping
    from stickslip.fe.scene import SceneParams

    for name in fe_cfg["scenes"]:
        mapping = scene_mapping(fe_cfg, name)
        try:
            SceneParams.from_mapping(
                {k: v for k, v in mapping.items() if k in ("beam", "disc", "contact", "solver")}
            )
        except (ValueError, TypeError, KeyError) as exc:
            raise ValueError(f"fe.scenes.{name}: {exc}") from None
    refs = [(f"fe.sweeps.{n}.base", sw["base"]) for n, sw in fe_cfg["sweeps"].items()]
    refs += [(f"fe.{study}.base", fe_cfg[study]["base"]) for study in FE_STUDIES]
    refs += [(f"fe.cross_scene.{n}", s) for n, pair in fe_cfg["cross_scene"].items() for s in pair[:2]]
    for key, scene in refs:
        if scene not in fe_cfg["scenes"]:
            raise ValueError(f"{key}: {scene!r} is not a scene of fe.scenes ({sorted(fe_cfg['scenes'])})")
    table = fe_cfg["friction_table"]
    if table not in producible and not Path(table).is_file():
        raise ValueError(
            f"fe.friction_table: {table!r} does not exist and no rule writes it (rule friction_table writes {producible})"
        )


check_fe_config(config["fe"], ["results/onedof/friction_mu_vr.csv"])


rule fe_scene:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{scene}.nc",
    log:
        "results/logs/fe_scene/{scene}.log",
    benchmark:
        "results/benchmarks/fe_scene/{scene}.tsv"
    wildcard_constraints:
        scene="|".join(FE_SCENES),
    script:
        "../scripts/fe_scene.py"


rule fe_sweep:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{sweep}.nc",
    log:
        "results/logs/fe_sweep/{sweep}.log",
    benchmark:
        "results/benchmarks/fe_sweep/{sweep}.tsv"
    wildcard_constraints:
        sweep="|".join(FE_SWEEPS),
    script:
        "../scripts/fe_sweep.py"


rule fe_study:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{study}.nc",
    log:
        "results/logs/fe_study/{study}.log",
    benchmark:
        "results/benchmarks/fe_study/{study}.tsv"
    wildcard_constraints:
        study="|".join(FE_STUDIES),
    params:
        kind=lambda wc: wc.study,
    script:
        "../scripts/fe_study.py"


rule fe_cross_scene:
    input:
        sorted({f"results/fe/{s}.nc" for pair in config["fe"]["cross_scene"].values() for s in pair[:2]}),
    output:
        "results/fe/cross_scene.nc",
    log:
        "results/logs/fe_cross_scene/cross_scene.log",
    benchmark:
        "results/benchmarks/fe_cross_scene/cross_scene.tsv"
    script:
        "../scripts/fe_cross.py"


rule fe_figure:
    input:
        "results/fe/{scene}.nc",
    output:
        report(
            "results/figures/fe/{scene}.png",
            caption=REPORT_CAPTION_FILE,
            category="Beam on rotating disc (Sections 9-12)",
            labels={"scene": "{scene}"},
        ),
    log:
        "results/logs/fe_figure/{scene}.log",
    benchmark:
        "results/benchmarks/fe_figure/{scene}.tsv"
    wildcard_constraints:
        scene="|".join(FE_SCENES),
    script:
        "../scripts/fe_figure.py"


FE_DATASETS = (
    [f"results/fe/{s}.nc" for s in FE_SCENES]
    + [f"results/fe/{s}.nc" for s in FE_SWEEPS]
    + [f"results/fe/{s}.nc" for s in FE_STUDIES]
    + ["results/fe/cross_scene.nc"]
)


rule fe_notebook:
    input:
        notebook="notebooks/section_09_12_beam_on_disc.py",
        data=FE_DATASETS,
        figures=[f"results/figures/fe/{s}.png" for s in FE_SCENES],
    output:
        report(
            "results/notebooks/section_09_12_beam_on_disc.html",
            caption=REPORT_CAPTION_FILE,
            category="Notebooks",
            labels={"notebook": "section_09_12_beam_on_disc"},
        ),
    log:
        "results/logs/fe_notebook/section_09_12_beam_on_disc.log",
    benchmark:
        "results/benchmarks/fe_notebook/section_09_12_beam_on_disc.tsv"
    params:
        python=sys.executable,
    shell:
        "{params.python} workflow/scripts/render_notebook.py {input.notebook} {output} > {log} 2>&1"


ALL_TARGETS.extend(FE_DATASETS)
ALL_TARGETS.extend(f"results/figures/fe/{s}.png" for s in FE_SCENES)
ALL_TARGETS.append("results/notebooks/section_09_12_beam_on_disc.html")
