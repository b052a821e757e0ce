# Shared definitions for every rules file: config validation, target list, helpers.
import re
import sys
from functools import cache
from glob import glob
from pathlib import Path

from stickslip.pipeline.config import drop_removed, validate_config
from stickslip.schema.base import as_params, as_written, canonical
from stickslip.claims.load import ClaimsError, check_claims, load_claims, required_datasets
from stickslip.io.run_variables import run_dataset_variables
import stickslip.catalogue as paths
from stickslip.catalogue import onedof_catalogue, onedof_dataset, sweep_dataset
from stickslip.pipeline.code_deps import code_hash, module_file
from stickslip.studies.fe_config import effective_fe, job_config as fe_job_config

#: Files a rule writes that the config may name as inputs before they exist.
PRODUCIBLE = [paths.friction_table("csv")]

#: Relative to the working directory (the project folder), so a moved project keeps its inputs' names.
CLAIM_FILES = sorted(glob("config/claims/*.yaml"))
#: The claims rows, read once at parse time for every rule that needs them (and the config check).
CLAIMS = load_claims(CLAIM_FILES)

# An override file removes an entry by setting it to null; then every config value is checked, before any
# job starts, an error naming its key (stickslip.pipeline.config).
drop_removed(config)
#: The config as one typed object (stickslip.schema.PipelineConfig): the rules read it, never the mapping.
CFG = validate_config(config, producible=PRODUCIBLE, sources=CONFIG_FILES, claims=CLAIMS)


#: Perturbation ensemble of every dataset a claim reads (stickslip.ensemble).
ENSEMBLE = as_params(CFG.ensemble)

#: The pinned set of claim ids: a deleted row or claims file is an error naming the ids it lost.
CLAIM_IDS_FILE = "config/claims/ids.txt"
#: Every product the config makes, path -> Entry (stickslip.catalogue): a claimed path must be one of them.
CATALOGUE = paths.catalogue(CFG)
check_claims(
    CLAIMS,
    CFG.claims.readings,
    catalogue=CATALOGUE,
    known_readings=[*CFG.onedof.readings, *CFG.fe.readings],
    pinned_ids=[
        line.strip()
        for line in Path(CLAIM_IDS_FILE).read_text().splitlines()
        if line.strip() and not line.startswith("#")
    ],
)
#: Every dataset some claim reads: these carry a perturbation ensemble, so each claim has a spread.
CLAIMED_DATASETS = set(required_datasets(CLAIMS, CFG.claims.readings))


def outputs(rule, flags=None, **wildcards):
    """The rule's outputs as the catalogue declares them (stickslip.catalogue.PRODUCTS), named as its script
    reads them; ``flags``: output name -> Snakemake flag for each of its files (report, temp, directory)."""
    flags = flags or {}
    out = paths.outputs(CFG, rule, **wildcards)
    for name, flag in flags.items():
        out[name] = [flag(p) for p in out[name]] if isinstance(out[name], list) else flag(out[name])
    return out


def products_of(*rules):
    """Every catalogue path the rules write, wildcards filled with each name of the config."""
    return [path for path, entry in CATALOGUE.items() if entry.rule in rules]


#: The software of every rule, for `--sdm conda` (the default run uses the project's venv: `make figures`).
CONDA_ENV = "../envs/stickslip.yaml"

#: Longest jobs first (their typical seconds on 2 cores, from results/benchmarks): on a CPU-bound build this
#: lets both cores finish together, and the FE and study jobs the claims table and notebooks wait for are
#: not left to the end (Snakemake otherwise picks among ready jobs without knowing their length).
PRIORITY = {
    # no job of its own is long, but every FE job (~100 s of CPU) waits for its table: first
    "friction_table": 40,
    "inverse_study": 35,
    "methods_work_precision": 30,
    "methods_failure_map": 15,
    "fe_model_comparison": 14,
    # the continuum over a claim's window: ~45 s of CPU, the longest FE job; started early so it is no tail
    "fe_continuum_window": 30,
    "onedof_sweeps": 10,
    "fe_figures": 10,
    "fe_studies": 10,
    # the default reading runs the paper's 1 s window: ~30 s, and the FE figures and the claims wait for it
    "fe_reading": 25,
}

#: Final outputs; every rules file appends its own.
ALL_TARGETS = []

#: Every 1-DOF run's dataset path -> its run (scene, reading, method): paths are looked up, never parsed.
ONEDOF_CATALOGUE = onedof_catalogue(CFG.onedof)

#: One caption template for every figure of `snakemake --report` (written by rule report_captions). An
#: absolute path under the working directory, since report() resolves captions against the rules folder.
REPORT_CAPTIONS = paths.report_captions()
REPORT_CAPTION_FILE = str(Path(REPORT_CAPTIONS).resolve())


def report_of(category, label=None, **more):
    """The report flag of each file of an output (``outputs(flags=...)``): the one caption template, the
    category, and ``label`` (when given) the file's name."""
    labels = (lambda p: {"labels": {label: Path(p).stem}}) if label else (lambda p: {})
    return lambda p: report(p, caption=REPORT_CAPTION_FILE, category=category, **labels(p), **more)


#: The run the friction table is measured along (onedof.friction_table: scene, reading, method).
TABLE_RUN = CFG.onedof.friction_table


SRC = Path(workflow.basedir) / "src"


def rule_code_hash(rule):
    """Hash of the package modules a rule's job can import: from its script, the `python -m` modules and
    scripts of its shell command, and the notebooks among its inputs."""
    entries = []
    if rule.script:
        entries.append(Path(rule.basedir.get_path_or_uri(secret_free=True)) / rule.script)
    if rule.shellcmd:
        entries += [module_file(SRC, m) for m in re.findall(r"-m (stickslip[\w.]*)", rule.shellcmd)]
        entries += [Path(p) for p in re.findall(r"(workflow/scripts/\S+\.py)", rule.shellcmd)]
    entries += [Path(f) for f in rule.input if isinstance(f, str) and f.endswith(".py")]
    return code_hash([e for e in entries if e is not None], SRC)


def catalogue_datasets(rules):
    """Every catalogue dataset named as an output (temporary outputs aside), for the default target; a missing
    dataset is then rebuilt by the default build, as make rebuilds a missing file. (Snakemake checks an
    intermediate only when something downstream must re-run: a deleted dataset no rule-all input named
    stayed gone.) The final products (pages, tables) are rule-all inputs where the config builds them. Outputs
    with wildcards are left out; the catalogue lists every reading of a
    sweep, the config builds a few; the build's record of what it wrote covers those (`make figures`,
    stickslip.pipeline.build)."""
    named = {
        str(o) for rule in rules for o in rule.output if not o.flags.get("temp") and not o.contains_wildcard()
    }
    return [p for p in CATALOGUE if p in named and p.endswith(".nc")]


def check_inputs_producible(rules):
    """Every dataset a claim reads and every file a notebook reads is an output of some rule. Snakemake would
    take an existing file whose producer is gone for a source file and never rebuild its consumers."""

    outputs = [(rule, o) for rule in rules for o in rule.products()]

    @cache
    def producible(path):
        return any(o.match(path) for _, o in outputs)

    run_variables = run_dataset_variables()
    check_claims(
        CLAIMS,
        CFG.claims.readings,
        producible=producible,
        variables_of=lambda path: run_variables if path in ONEDOF_CATALOGUE else None,
    )
    for name in CFG.notebooks:
        for path in notebook_inputs(name):
            if paths.is_result(path) and path not in CATALOGUE:
                raise ClaimsError(
                    f"notebooks.{name}.inputs: {path!r} is not a catalogue path (stickslip.catalogue): no rule writes it"
                )
            # a source file of the project (a claims file) may be read as it is; a result must be made
            if not producible(path) and (paths.is_result(path) or not Path(path).is_file()):
                raise ClaimsError(f"notebooks.{name}.inputs: no rule writes {path!r}")


def _names(value):
    return None if value is None else [value] if isinstance(value, str) else sorted(set(value))


def onedof_subconfig(readings=None, scenes=None, methods=None, study=None):
    """The part of the config a 1-DOF job reads, passed as its params: the defaults, the named readings,
    scenes and methods (a name or a list; None: all) and at most one study section. Snakemake re-runs a job
    whose params change, so an edit re-runs exactly the jobs that read the edited value."""
    onedof = CFG.onedof
    sub = {"baseline": onedof.baseline, "defaults": onedof.defaults}
    for key, names in (("readings", readings), ("scenes", scenes), ("methods", methods)):
        names, entries = _names(names), getattr(onedof, key)
        sub[key] = entries if names is None else {n: entries[n] for n in names}
    if study is not None:
        sub[study] = getattr(onedof, study)
    return {"onedof": as_params(sub)}


def onedof_runs():
    """scene -> sorted (reading, method) pairs that any figure, claim, notebook or the friction table reads:
    one job per scene computes them all (each run takes milliseconds, a job's start-up seconds)."""
    wanted = set(CLAIMED_DATASETS)
    for fig in CFG.onedof.figures:
        wanted.update(figure_datasets(fig))
    for name in CFG.notebooks:
        wanted.update(notebook_inputs(name))
    table = CFG.onedof.friction_table
    wanted.add(onedof_dataset(table.scene, table.reading, table.method))
    runs = {}
    for run in filter(None, map(ONEDOF_CATALOGUE.get, wanted)):
        runs.setdefault(run.name("scene"), set()).add((run.name("reading"), run.name("method")))
    return {scene: sorted(pairs) for scene, pairs in sorted(runs.items())}


def figure_datasets(figure):
    fig = CFG.onedof.figures[figure]
    return [onedof_dataset(fig.scene, r, m) for r in fig.readings for m in fig.methods]


# -- notebooks ------------------------------------------------------------------------------------------


def notebook_params(name):
    """What the notebook is told: its figures' and sweep figures' specs (scene, readings, methods), the
    claims readings and the critical-speed readings, so it draws exactly what the DAG built for it, and the
    notes of the claims it reads."""
    spec, onedof = CFG.notebooks[name], CFG.onedof
    inputs = set(notebook_inputs(name))
    return {
        "figures": {fig: as_params(onedof.figures[fig]) for fig in spec.figures or []},
        "sweep_figures": {fig: as_params(onedof.sweep_figures[fig]) for fig in spec.sweep_figures or []},
        "claims_readings": CFG.claims.readings,
        "critical_speed_readings": critical_speed_readings(),
        # each note of the claims files it reads, from the rows the parse checked (no job parses them again)
        "claim_notes": {c.id: c.note for c in CLAIMS if c.file in inputs},
    }


def critical_speed_readings():
    critical = CFG.onedof.critical_speed
    return [] if critical is None else critical.readings


def notebook_inputs(name):
    """Every file the notebook reads. An `inputs:` entry containing `{reading}` is expanded over the claims
    readings (the readings whose datasets the claims table already requires), `{critical_reading}` over the
    readings of the critical-speed continuation."""
    spec = CFG.notebooks[name]
    expand_over = {"reading": CFG.claims.readings, "critical_reading": critical_speed_readings()}
    files = []
    for path in spec.inputs or []:
        key = next((k for k in expand_over if f"{{{k}}}" in path), None)
        files += [path.format(**{key: r}) for r in expand_over[key]] if key else [path]
    for fig in spec.figures or []:
        files += figure_datasets(fig)
        files += [paths.figure(fig, r) for r in CFG.onedof.figures[fig].readings]
    for fig in spec.sweep_figures or []:
        sw = CFG.onedof.sweep_figures[fig]
        files += [sweep_dataset(sw.sweep, r, d) for r in sw.readings for d in (False, True)]
        files += [paths.figure(fig, r) for r in sw.readings]
    return list(dict.fromkeys(files + [paths.claims_table(), paths.figure_verdicts()]))


def notebook_paper_figures(name):
    """The paper figures a notebook sits beside, from what it shows: the paper figures of each image it
    reads (the catalogue's, from the config's paper_figures maps) and of the rows of each claims file it
    reads. A dataset it reads to compare with is not a figure it shows."""
    inputs = notebook_inputs(name)
    images = [CATALOGUE[path] for path in inputs if path in CATALOGUE and CATALOGUE[path].kind == "figure"]
    figures = {n for entry in images for n in entry.figures}
    figures |= {n for claim in CLAIMS if claim.file in inputs for n in claim.figures}
    return sorted(figures)


def fe_scene_of(path):
    """The FE scene a claim's dataset is a run of (beam in any reading, continuum, continuum window), None
    for any other dataset: looked up in the catalogue."""
    entry = CATALOGUE.get(path) if isinstance(path, str) else None
    fe_kinds = ("fe_scene", "fe_continuum", "fe_continuum_window")
    return entry.name("scene") if entry is not None and entry.kind in fe_kinds else None


# -- sweeps and maps ----------------------------------------------------------------------------------


def dense_map_subconfig(name):
    """Everything ``studies.specs.dense_map`` reads: the map, the default chunk size and the 1-DOF scene,
    reading and method it runs (a job re-runs when any of them changes)."""
    entry = CFG.dense_map.maps[name]
    sub = onedof_subconfig(entry.reading, entry.scene, entry.method)
    section = as_params(CFG.dense_map.model_copy(update={"maps": {name: entry}}))
    return {**sub, "dense_map": section}


def inverse_onedof_config():
    """The part of the 1-DOF config the study reads: the baseline, the defaults, and only the scenes and
    sweeps its claims' datasets, its one-scene figures and those sweeps' base scenes name (an unrelated new
    scene re-runs nothing). A claim id not among the project's claims files (another claims_glob) keeps
    every scene and sweep."""
    from stickslip.inverse.problem import runs_by_dataset

    onedof, figures = CFG.onedof, CFG.inverse.figures.values()
    ids = {cid for fig in figures for cid in fig.claims}
    rows = {c.id: c for c in CLAIMS}
    keep = {k: getattr(onedof, k) for k in ("baseline", "defaults", "scenes", "sweeps")}
    if not ids <= set(rows):
        return as_params(keep)
    runs = runs_by_dataset(onedof.scenes, onedof.sweeps)
    named = [runs[rows[i].dataset] for i in sorted(ids) if rows[i].dataset in runs]
    sweeps = sorted({name for kind, name in named if kind == "sweep"})
    base = onedof.baseline.scene
    scenes = {name for kind, name in named if kind == "scene"} | {base}
    scenes |= {fig.scene for fig in figures if fig.scene is not None}
    scenes |= {onedof.sweeps[s].scene or base for s in sweeps}
    keep["scenes"] = {name: onedof.scenes[name] for name in scenes if name in onedof.scenes}
    keep["sweeps"] = {name: onedof.sweeps[name] for name in sweeps}
    return as_params(keep)
