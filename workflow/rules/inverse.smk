# The inverse study (a fit beside the claims table; it changes no pinned claim).
# `inverse.long: true` in config/inverse.yaml gives the long run (longer chains, exact leave-one-out refits).

INVERSE_FIGURES = list(config["inverse"]["figures"]) + ["joint"]
INVERSE_FAMILIES = list(config["inverse"]["families"])
INVERSE_MODE = "long" if config["inverse"].get("long", False) else "default"
INVERSE_CORNER = config["inverse"]["settings"][INVERSE_MODE].get("corner", [])


def inverse_onedof_config():
    """The part of the 1-DOF config the study reads: the baseline, the defaults, and only the scenes and
    sweeps its claims' datasets, its one-scene figures and those sweeps' base scenes name (an unrelated new
    scene re-runs nothing). A claim id not among the project's claims files (another claims_glob) keeps
    every scene and sweep."""
    from stickslip.inverse.problem import runs_by_dataset

    inv = config["inverse"]
    ids = {cid for fig in inv["figures"].values() for cid in fig.get("claims", [])}
    rows = {c.id: c for c in CLAIMS}
    keep = {k: ONEDOF[k] for k in ("baseline", "defaults", "scenes", "sweeps")}
    if not ids <= set(rows):
        return canonical(keep)
    runs = runs_by_dataset(ONEDOF)
    named = [runs[rows[i].dataset] for i in sorted(ids) if rows[i].dataset in runs]
    sweeps = sorted({name for kind, name in named if kind == "sweep"})
    scenes = {name for kind, name in named if kind == "scene"} | {BASELINE["scene"]}
    scenes |= {fig["scene"] for fig in inv["figures"].values() if "scene" in fig}
    scenes |= {ONEDOF["sweeps"][s].get("scene") or BASELINE["scene"] for s in sweeps}
    keep["scenes"] = {name: ONEDOF["scenes"][name] for name in scenes if name in ONEDOF["scenes"]}
    keep["sweeps"] = {name: ONEDOF["sweeps"][name] for name in sweeps}
    return canonical(keep)


rule inverse_study:
    input:
        claims=sorted(str(p) for p in Path(".").glob(config["inverse"]["claims_glob"])),
    output:
        **{name: paths.inverse_table(name) for name in paths.INVERSE_TABLES},
        datasets=[paths.inverse_dataset(f) for f in INVERSE_FIGURES],
        corner=[paths.inverse_corner(f, fam) for f in INVERSE_CORNER for fam in INVERSE_FAMILIES],
    log:
        paths.log("inverse_study"),
    benchmark:
        paths.benchmark("inverse_study")
    priority: PRIORITY["inverse_study"]
    conda:
        CONDA_ENV
    params:
        # the inverse section as written: a hypothesis is named by its first key, listed in file order
        config={"onedof": inverse_onedof_config(), "inverse": config["inverse"]},
    script:
        "../scripts/inverse_study.py"


ALL_TARGETS.extend(rules.inverse_study.output)
