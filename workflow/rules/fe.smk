# Beam on rotating disc (paper Sections 9-12, issues 5 and 11). Scene and reading names come from the typed
# fe section (CFG.fe, checked once for the whole workflow by stickslip.pipeline.config).

#: The fe section with the long-run switch applied; each job's params are the part of it that job reads,
#: resolved (stickslip.studies.fe_config.job_config): a value re-runs exactly the jobs that read it.
FE_EFFECTIVE = effective_fe(CFG)
FE_SCENES = list(FE_EFFECTIVE.scenes)
FE_READINGS = list(FE_EFFECTIVE.readings)
FE_DEFAULT_READING = FE_READINGS[0]
FE_SWEEPS = list(FE_EFFECTIVE.sweeps)
FE_FRICTION = FE_EFFECTIVE.friction_table
#: The scenes the studies start from (sweeps, convergence, stability, increments).
FE_STUDY_SECTIONS = ("sweeps", "convergence", "stability", "increments")
#: The paper's beam-on-disc figures, one PNG each: the config's registry (fe.paper_figures: figure -> scenes).
FE_PAPER_FIGURES = sorted(FE_EFFECTIVE.paper_figures)
FE_STUDY_BASES = sorted(
    {sw.base for sw in FE_EFFECTIVE.sweeps.values()}
    | {getattr(FE_EFFECTIVE, k).base for k in FE_STUDY_SECTIONS[1:]}
    | set(FE_EFFECTIVE.stability.speeds.values())
)


rule fe_reading:
    """Every paper scene under one FE reading, and the cross-scene ratios (one job: the scenes take
    ~0.3 s CPU each, less than a job's start-up)."""
    input:
        friction=FE_FRICTION,
    output:
        **outputs("fe_reading", reading="{fe_reading}"),
    log:
        paths.log("fe_reading", "{fe_reading}"),
    benchmark:
        paths.benchmark("fe_reading", "{fe_reading}")
    wildcard_constraints:
        fe_reading="|".join(FE_READINGS),
    priority: PRIORITY["fe_reading"]
    conda:
        CONDA_ENV
    params:
        config=lambda wildcards: fe_job_config(
            FE_EFFECTIVE, scenes=FE_SCENES, reading=wildcards.fe_reading, sections=["cross_scene"]
        ),
        # the scene of each output, in the same order (names are looked up, never parsed from a path)
        scenes=FE_SCENES,
        ensemble=ENSEMBLE,
    script:
        "../scripts/fe_reading.py"


rule fe_studies:
    """The sweeps, the convergence and stability studies and the continuum increment counts in one job (each
    takes 1-3 s CPU, a job's start-up ~5 s)."""
    input:
        friction=FE_FRICTION,
    output:
        **outputs("fe_studies"),
    log:
        paths.log("fe_studies", "studies"),
    benchmark:
        paths.benchmark("fe_studies", "studies")
    priority: PRIORITY["fe_studies"]
    conda:
        CONDA_ENV
    params:
        config=fe_job_config(FE_EFFECTIVE, scenes=FE_STUDY_BASES, sections=FE_STUDY_SECTIONS),
        sweeps=FE_SWEEPS,  # the sweep of each output, in the same order
        ensemble=ENSEMBLE,
    script:
        "../scripts/fe_studies.py"


#: FITS of the tip support to the paper's Fig. 21 centre, labelled as fits: one per disc speed (the fitted
#: stiffness is the same closed form; the speed decides the growth claims). Dataset name -> base scene.
FE_SETUP_FITS = paths.FE_SETUP_FITS


rule fe_setup_fit:
    """FIT, beside the forward replication: the tip on a soft support whose stiffness puts the static contact
    corner at Fig. 21's centre (the claims row's value), on a penalty scene at one disc speed."""
    input:
        friction=FE_FRICTION,
    output:
        **outputs("fe_setup_fit", name="{fe_fit}"),
    log:
        paths.log("fe_setup_fit", "{fe_fit}"),
    benchmark:
        paths.benchmark("fe_setup_fit", "{fe_fit}")
    wildcard_constraints:
        fe_fit="|".join(FE_SETUP_FITS),
    priority: PRIORITY["fe_studies"]
    conda:
        CONDA_ENV
    params:
        config=lambda wildcards: fe_job_config(FE_EFFECTIVE, scenes=[FE_SETUP_FITS[wildcards.fe_fit]]),
        ensemble=ENSEMBLE,
        base=lambda wildcards: FE_SETUP_FITS[wildcards.fe_fit],
        centre=next(c.value for c in CLAIMS if c.id == "s9_oscillation_centre"),
    script:
        "../scripts/fe_setup_fit.py"


#: scenes the continuum also runs over a claim's window (config fe.comparison.claim_windows)
FE_WINDOW_SCENES = list(FE_EFFECTIVE.comparison.claim_windows)


rule fe_continuum_window:
    """The continuum strip over a claim's window at dt and dt/2 (step-halving member as its ensemble): the
    model that decides claims where the beam is not adequate, and the check of the beam where it is."""
    input:
        friction=FE_FRICTION,
    output:
        **outputs("fe_continuum_window", scene="{scene}"),
    log:
        paths.log("fe_continuum_window", "{scene}"),
    benchmark:
        paths.benchmark("fe_continuum_window", "{scene}")
    wildcard_constraints:
        scene="|".join(FE_WINDOW_SCENES),
    priority: PRIORITY["fe_continuum_window"]
    conda:
        CONDA_ENV
    params:
        config=lambda wildcards: fe_job_config(
            FE_EFFECTIVE, scenes=[wildcards.scene], sections=["comparison"]
        ),
    script:
        "../scripts/fe_continuum_window.py"


rule fe_model_comparison:
    """Continuum strip (the paper's kind of model) and beam on every paper scene, same window; over a
    claim's window the continuum runs of fe_continuum_window against the default reading's beam."""
    input:
        friction=FE_FRICTION,
        window=[paths.fe_continuum_window(s) for s in FE_WINDOW_SCENES],
        beam=[paths.fe_scene(FE_DEFAULT_READING, s) for s in FE_WINDOW_SCENES],
    output:
        **outputs("fe_model_comparison"),
    log:
        paths.log("fe_model_comparison", "model_comparison"),
    benchmark:
        paths.benchmark("fe_model_comparison", "model_comparison")
    priority: PRIORITY["fe_model_comparison"]
    conda:
        CONDA_ENV
    params:
        config=fe_job_config(FE_EFFECTIVE, scenes=FE_SCENES, sections=["comparison"]),
        # the scene of each continuum output and of each window input, in the same order
        scenes=FE_SCENES,
        window_scenes=FE_WINDOW_SCENES,
    script:
        "../scripts/fe_comparison.py"


#: The claims file of Sections 9-12 (its rows, as the parse read them, are the FE readings' claims).
FE_CLAIMS_FILE = "config/claims/sections_09_12.yaml"


rule fe_readings_claims:
    """Every FE claim row evaluated under every FE reading (the claims table checks the default one)."""
    input:
        claims=FE_CLAIMS_FILE,
        comparison=paths.fe_model_comparison("csv"),
        # the continuum rows of the windows: one reading, never re-pointed per FE reading
        data=products_of("fe_reading", "fe_studies", "fe_setup_fit", "fe_continuum_window")
        + [paths.fe_peer_calculix("nc")],
    output:
        **outputs("fe_readings_claims"),
    log:
        paths.log("fe_readings_claims", "readings_claims"),
    benchmark:
        paths.benchmark("fe_readings_claims", "readings_claims")
    conda:
        CONDA_ENV
    params:
        claims=[claim for claim in CLAIMS if claim.file == FE_CLAIMS_FILE],  # no job parses the file again
        readings=FE_READINGS,
        scenes=FE_SCENES,
        cross_scene=canonical(FE_EFFECTIVE.cross_scene),
    script:
        "../scripts/fe_readings_claims.py"


FE_CATEGORY = "Beam on rotating disc (Sections 9-12)"


rule fe_figures:
    """Every FE figure in one job (a figure takes ~0.5 s, a job's start-up ~5 s): one per paper figure 21-36
    (default reading, both disc speeds side by side), the paper scenes (default reading, continuum overlaid
    over its window), the readings overview, convergence and stability."""
    input:
        beam=[paths.fe_scene(FE_DEFAULT_READING, s) for s in FE_SCENES],
        continuum=[paths.fe_continuum(s) for s in FE_SCENES],
        readings=[paths.fe_scene(r, s) for r in FE_READINGS for s in FE_SCENES],
        convergence=paths.fe_study("convergence"),
        stability=paths.fe_study("stability"),
    output:
        **outputs(
            "fe_figures",
            flags={
                "scenes": report_of(FE_CATEGORY),
                "paper": report_of(FE_CATEGORY, subcategory="One per paper figure"),
            },
        ),
    log:
        paths.log("fe_figures", "figures"),
    benchmark:
        paths.benchmark("fe_figures", "figures")
    priority: PRIORITY["fe_figures"]
    conda:
        CONDA_ENV
    params:
        readings=FE_READINGS,
        scenes=FE_SCENES,
        # the paper figures in the order of output.paper, and the scenes each draws (config fe.paper_figures)
        paper_figure_numbers=FE_PAPER_FIGURES,
        paper_figures=FE_EFFECTIVE.paper_figures,
        # the paper's Section 9 numbers the readings overview marks, from the claims files
        reported={
            c.variable: c.value
            for c in CLAIMS
            if c.id in ("s9_max_horizontal_displacement", "s9_oscillation_centre")
        },
        # per scene: the paper's numbers in mm that its claims compare with, drawn on the scene figure
        scene_reported={
            s: {
                c.variable.replace("_", " "): c.value
                for c in CLAIMS
                if c.kind == "value" and c.unit == "mm" and fe_scene_of(c.dataset) == s
            }
            for s in FE_SCENES
        },
        default_reading=FE_DEFAULT_READING,
        # per paper figure 21-36: the paper's numbers in mm or mm/s its claims rows name, drawn as lines,
        # and its times in s (drawn as vertical lines)
        paper_reported={
            n: [
                {"label": c.variable.replace("_", " "), "value": c.value, "unit": c.unit}
                for c in CLAIMS
                if n in c.figures and c.unit in ("mm", "mm s-1", "s") and c.value is not None
            ]
            for n in FE_PAPER_FIGURES
        },
        # Fig. 31: the "several times the initial normal force" the claims row compares with
        paper_normal_force_ratio=next(
            (c.rhs.value for c in CLAIMS if c.id == "s11_normal_force_several_times"), None
        ),
    script:
        "../scripts/fe_figures.py"


# every FE dataset but the continuum strip's and the model comparison's dataset, and every FE figure
ALL_TARGETS.extend(
    products_of("fe_reading", "fe_studies", "fe_setup_fit", "fe_continuum_window", "fe_readings_claims")
    + [paths.fe_model_comparison("csv")]
    + products_of("fe_figures")
)
