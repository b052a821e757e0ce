"""Where every dataset, table, figure, notebook, log and benchmark of the pipeline lives, defined once.

One small function per family makes a path (``onedof_dataset``, ``fe_scene``, ``figure``, ``log``, ...):
rules, claims, notebooks, the page and the inverse study call these, and nothing else builds, parses or
rewrites a ``results/`` path (``tests/pipeline/test_catalogue.py`` greps). A rule with a wildcard passes it
through as text: ``fe_scene("{fe_reading}", "{scene}")``.

``catalogue(config)`` lists every entry the config makes, built forward from the config names (every
scene x reading x method, ...): a path is looked up, never parsed; a path that is not in it is no product of
the pipeline, whatever it looks like. Each ``Entry`` says what it is (``kind``), the names that make it, the
rule that writes it and the paper figures it shows (from the config's ``paper_figures`` maps).

At the bottom of the package: it imports nothing from the project, so every layer may use it.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass

RESULTS = "results"

# ------------------------------------------------------------------------------------------------- 1-DOF


def onedof_dataset(scene: str, reading: str, method: str) -> str:
    """The dataset of one 1-DOF run (rule ``simulate_onedof_<scene>``)."""
    return f"{RESULTS}/onedof/{scene}/{reading}/{method}.nc"


def sweep_dataset(sweep: str, reading: str, dense: bool = False) -> str:
    """The dataset of one sweep for one reading, at the paper's values or dense (rule ``onedof_sweeps``)."""
    return f"{RESULTS}/onedof/sweeps/{sweep}{'_dense' if dense else ''}/{reading}.nc"


def eq6_curve() -> str:
    """Fig. 4: Eq. 6 as printed and the dimensionally correct curve (rule ``eq6_curve``)."""
    return f"{RESULTS}/onedof/fig04/eq6.nc"


def friction_table(ext: str = "csv") -> str:
    """Fig. 17: mu(v_r) along the baseline, ``csv`` (the FE scenes' friction law) or ``nc``."""
    return f"{RESULTS}/onedof/friction_mu_vr.{ext}"


def critical_speed(reading: str) -> str:
    """The continuation over belt speed for one reading (rule ``critical_speed``)."""
    return f"{RESULTS}/onedof/critical_speed/{reading}.nc"


def critical_speed_summary(ext: str = "csv") -> str:
    """The critical speed of every reading, ``csv`` or ``nc`` (rule ``critical_speed_summary``)."""
    return f"{RESULTS}/onedof/critical_speed.{ext}"


def dense_map(name: str) -> str:
    """One dense parameter map, every chunk merged (rule ``dense_map_merge``)."""
    return f"{RESULTS}/dense_map/{name}.nc"


def dense_map_chunk(name: str, chunk) -> str:
    """One chunk of a dense map (rule ``dense_map_chunk``; temporary)."""
    return f"{RESULTS}/dense_map/chunks/{name}/{chunk}.nc"


def methods_work_precision(scene: str) -> str:
    """The work-precision study of the integration methods on one scene."""
    return f"{RESULTS}/methods/{scene}_work_precision.nc"


def methods_failure_map() -> str:
    return f"{RESULTS}/methods/failure_map.nc"


def validation_peer_table(law: str) -> str:
    """Switch solver vs CVODE for one friction law (rule ``validation_peer``)."""
    return f"{RESULTS}/validation/peer_{law}.csv"


def validation_peer() -> str:
    return f"{RESULTS}/validation/peer.nc"


def validation_round_trip(ext: str = "nc") -> str:
    """The 1-DOF model driven by the Fig. 17 table, ``nc`` or ``csv`` (rule ``validation_round_trip``)."""
    return f"{RESULTS}/validation/round_trip.{ext}"


def validation_methods(law: str) -> str:
    """The methods study on one nonlinear friction law (rule ``validation_methods``)."""
    return f"{RESULTS}/validation/methods_{law}.nc"


# ---------------------------------------------------------------------------------------- beam on disc (FE)

#: The FE studies that are datasets of their own beside the sweeps (rule ``fe_studies``).
FE_STUDIES = ("convergence", "stability")
#: FITS of the tip support to Fig. 21's centre (rule ``fe_setup_fit``): dataset name -> the scene it starts
#: from, one per disc speed.
FE_SETUP_FITS = {
    "setup_fit": "section11_penalty_15p2rpm",
    "setup_fit_0p5mm_s": "section11_penalty_0p5mm_s",
}
#: The CalculiX peer's two linear decks (rule ``fe_peer_calculix``).
FE_PEER_DECKS = ("peer_free", "peer_propped")
#: A scene's CalculiX variant deck is ``fe_deck(scene + FE_CCX_SUFFIX)`` (rule ``fe_decks``).
FE_CCX_SUFFIX = "_ccx"


def fe_scene(reading: str, scene: str) -> str:
    """One paper scene under one FE reading (rule ``fe_reading``)."""
    return f"{RESULTS}/fe/{reading}/{scene}.nc"


def fe_cross_scene(reading: str) -> str:
    """The cross-scene ratios of one FE reading (rule ``fe_reading``)."""
    return f"{RESULTS}/fe/{reading}/cross_scene.nc"


def fe_study(name: str) -> str:
    """A dataset shared by every FE reading: a sweep, ``convergence``, ``stability``,
    ``continuum_increments`` (rule ``fe_studies``) or a setup fit (rule ``fe_setup_fit``)."""
    return f"{RESULTS}/fe/{name}.nc"


def fe_continuum(scene: str) -> str:
    """The continuum strip on one paper scene (rule ``fe_model_comparison``)."""
    return f"{RESULTS}/fe/continuum/{scene}.nc"


def fe_continuum_window(scene: str) -> str:
    """The continuum strip over a claim's window, at dt and dt/2 (rule ``fe_continuum_window``)."""
    return f"{RESULTS}/fe/continuum_window/{scene}.nc"


def fe_model_comparison(ext: str = "csv") -> str:
    """Continuum vs beam on every scene, ``csv`` or ``nc`` (rule ``fe_model_comparison``)."""
    return f"{RESULTS}/fe/model_comparison.{ext}"


def fe_readings_claims() -> str:
    """Every FE claim under every FE reading (rule ``fe_readings_claims``)."""
    return f"{RESULTS}/fe/readings_claims.csv"


def fe_peer_calculix(ext: str = "nc") -> str:
    """CalculiX as a peer of the continuum strip, ``nc`` or ``csv`` (rule ``fe_peer_calculix``)."""
    return f"{RESULTS}/fe/peer_calculix.{ext}"


def fe_deck(name: str) -> str:
    """An input deck: a scene for ABAQUS/Explicit or its CalculiX variant (``<scene>_ccx``, rule
    ``fe_decks``), or a CalculiX peer deck."""
    return f"{RESULTS}/fe/inp/{name}.inp"


# ------------------------------------------------------------------------------------------------ inverse


def inverse_table(name: str) -> str:
    """``summary``, ``hypotheses``, ``ranking``, ``numbers`` or ``conflicts`` (rule ``inverse_study``)."""
    return f"{RESULTS}/inverse/{name}.csv"


def inverse_dataset(figure: str) -> str:
    """The inverse study's fit of one figure (or ``joint``)."""
    return f"{RESULTS}/inverse/{figure}.nc"


def inverse_corner(figure: str, family: str) -> str:
    return f"{RESULTS}/inverse/corner/{figure}_{family}.png"


INVERSE_TABLES = ("summary", "hypotheses", "ranking", "numbers", "conflicts")

# ------------------------------------------------------------------------------------------------- claims


def claims_table(ext: str = "csv") -> str:
    """Every claim vs what the pipeline measures, ``csv`` or ``md`` (rule ``claims_table``)."""
    return f"{RESULTS}/claims/deviations.{ext}"


def claims_check() -> str:
    """The flag rule ``claims_check`` touches when every status is its pin."""
    return f"{RESULTS}/claims/check.ok"


def figure_verdicts() -> str:
    """Every paper figure's verdicts (rule ``figure_verdicts``)."""
    return f"{RESULTS}/claims/figure_verdicts.csv"


def reading_ranking(ext: str = "csv") -> str:
    """The readings ranked by the claims they reproduce, ``csv`` or ``nc`` (rule ``reading_ranking``)."""
    return f"{RESULTS}/claims/reading_ranking.{ext}"


def unreproduced_claims() -> str:
    return f"{RESULTS}/claims/unreproduced_claims.csv"


# ----------------------------------------------------------------------------- figures, notebooks, page


def figure(group: str, name: str) -> str:
    """A PNG: ``figure("fig02", reading)``, ``figure("fe", scene)``, ``figure("fe", "fig21")``,
    ``figure("methods", "failure_map")``, ``figure("dense_map", name)``, ``figure("critical_speed", "all")``.
    """
    return f"{RESULTS}/figures/{group}/{name}.png"


def notebook(name: str) -> str:
    """A rendered notebook (rule ``render_notebooks``, or ``methods_notebook``)."""
    return f"{RESULTS}/notebooks/{name}.html"


def report_captions() -> str:
    return f"{RESULTS}/report/captions.rst"


def page() -> str:
    """The replication page (rule ``replication_page``)."""
    return f"{RESULTS}/index.html"


def page_thumbs() -> str:
    """The page's thumbnails (a folder)."""
    return f"{RESULTS}/page/thumbs"


def page_previews() -> str:
    """Each linked dataset's ``stickslip show`` text as HTML (a folder: ``<path below results>.html``)."""
    return f"{RESULTS}/page/datasets"


def page_source_pages() -> str:
    """Each linked source file rendered with line anchors (a folder: ``<file>.html#L<n>``)."""
    return f"{RESULTS}/page/source"


def benchmark_summary(ext: str = "csv") -> str:
    """Wall time and peak memory of every job, per rule, ``csv`` or ``md``."""
    return f"{RESULTS}/benchmarks/summary.{ext}"


def log(rule: str, name: str | None = None) -> str:
    """A job's log: ``results/logs/<rule>/<name>.log``, or ``results/logs/<rule>.log`` for a rule with one."""
    return f"{RESULTS}/logs/{rule}.log" if name is None else f"{RESULTS}/logs/{rule}/{name}.log"


def benchmark(rule: str, name: str | None = None) -> str:
    """A job's benchmark table, laid out as its log."""
    folder = benchmarks_folder()
    return f"{folder}/{rule}.tsv" if name is None else f"{folder}/{rule}/{name}.tsv"


def fe_model_of(path: str) -> str | None:
    """``"continuum"`` for a product of the continuum strip (``fe_continuum``, ``fe_continuum_window``,
    ``continuum_increments``), ``"beam"`` for any other beam-on-disc product, None for the rest. The one place
    the FE layout is read back: a claims row is checked on its own, before a config (and so a catalogue) is
    at hand."""
    if not path.startswith(f"{RESULTS}/fe/"):
        return None
    return "continuum" if path.startswith(f"{RESULTS}/fe/continuum") else "beam"


def last_name(path: str) -> str:
    """The name every path function puts last (a scene, a study, a figure): what a claims row's dataset is
    matched by against the model comparison's rows, without a catalogue at hand."""
    return path.rsplit("/", 1)[-1].rsplit(".", 1)[0]


def benchmarks_folder() -> str:
    """Where every job's benchmark table is (``benchmark``)."""
    return f"{RESULTS}/benchmarks"


def is_benchmark(path: str) -> bool:
    """Whether a path is a job's benchmark table (``benchmark``)."""
    return path.startswith(benchmarks_folder() + "/")


def is_result(path: str) -> bool:
    """Whether a path names something the pipeline makes (as opposed to a source file of the project)."""
    return path.startswith(f"{RESULTS}/")


# ------------------------------------------------------------------------------------------- the records


@dataclass(frozen=True)
class Entry:
    """One product of the pipeline."""

    kind: str  #: the family, as the path function's name (``onedof_dataset``, ``fe_scene``, ``figure``, ...)
    names: tuple[tuple[str, str], ...]  #: the config names that make it, (key, name) pairs in order
    path: str
    rule: str  #: the rule that writes it
    figures: tuple[int, ...] = ()  #: the paper figures it shows, from the config's ``paper_figures`` maps

    def name(self, key: str) -> str:
        return dict(self.names)[key]


def _entry(kind, names: Mapping[str, str], path, rule, figures=()) -> Entry:
    return Entry(kind, tuple((k, str(v)) for k, v in names.items()), path, rule, tuple(sorted(figures)))


def same_entry(entries: Mapping[str, Entry], entry: Entry, **names: str) -> Entry | None:
    """The entry of the same kind as ``entry`` whose names are ``entry``'s with ``names`` changed (the same
    FE scene in another reading: ``same_entry(cat, e, reading="node1_upper")``); None if there is none."""
    wanted = tuple((k, names.get(k, v)) for k, v in entry.names)
    return next((e for e in entries.values() if e.kind == entry.kind and e.names == wanted), None)


def figures_of(paper_figures: Mapping | None) -> dict[str, tuple[int, ...]]:
    """name -> the paper figures it shows, from a ``{figure number: [names]}`` map."""
    out: dict[str, list[int]] = {}
    for number, names in (paper_figures or {}).items():
        for name in names:
            out.setdefault(name, []).append(int(number))
    return {name: tuple(sorted(numbers)) for name, numbers in out.items()}


def onedof_shows(onedof: Mapping) -> dict[str, tuple[int, ...]]:
    """What each 1-DOF run shows of the paper, from the ``paper_figures`` of the figures drawn from it:
    ``scene:<name>`` and ``sweep:<name>`` -> paper figures, and each figure's own name -> its figures."""
    out: dict[str, set[int]] = {}
    for name, fig in (onedof.get("figures") or {}).items():
        for key in (name, f"scene:{fig['scene']}"):
            out.setdefault(key, set()).update(fig.get("paper_figures") or ())
    for name, fig in (onedof.get("sweep_figures") or {}).items():
        for key in (name, f"sweep:{fig['sweep']}"):
            out.setdefault(key, set()).update(fig.get("paper_figures") or ())
    out["eq6"] = set((onedof.get("eq6") or {}).get("paper_figures") or ())
    return {key: tuple(sorted(numbers)) for key, numbers in out.items()}


def _onedof_entries(onedof: Mapping) -> Iterator[Entry]:
    shows = onedof_shows(onedof)
    for scene in onedof["scenes"]:
        for reading in onedof["readings"]:
            for method in onedof["methods"]:
                names = {"scene": scene, "reading": reading, "method": method}
                path = onedof_dataset(scene, reading, method)
                rule = f"simulate_onedof_{scene}"
                yield _entry("onedof_dataset", names, path, rule, shows.get(f"scene:{scene}", ()))
    for sweep in onedof.get("sweeps") or {}:
        for reading in onedof["readings"]:
            for dense in (False, True):
                names = {"sweep": sweep, "reading": reading, "dense": str(dense)}
                path = sweep_dataset(sweep, reading, dense)
                yield _entry("sweep_dataset", names, path, "onedof_sweeps", shows.get(f"sweep:{sweep}", ()))
    yield _entry("eq6_curve", {}, eq6_curve(), "eq6_curve", shows["eq6"])
    yield _entry(
        "figure", {"group": "fig04", "name": "eq6"}, figure("fig04", "eq6"), "eq6_curve", shows["eq6"]
    )
    for ext in ("csv", "nc"):
        yield _entry("friction_table", {"ext": ext}, friction_table(ext), "friction_table")
    for kind, section in (("onedof_figure", "figures"), ("sweep_figure", "sweep_figures")):
        for name, fig in (onedof.get(section) or {}).items():
            for reading in fig["readings"]:
                names = {"group": name, "name": reading}
                yield _entry("figure", names, figure(name, reading), f"{kind}_{name}", shows.get(name, ()))
    critical = onedof.get("critical_speed") or {}
    for reading in critical.get("readings", []):
        yield _entry("critical_speed", {"reading": reading}, critical_speed(reading), "critical_speed")
    if critical:
        for ext in ("csv", "nc"):
            yield _entry(
                "critical_speed_summary", {"ext": ext}, critical_speed_summary(ext), "critical_speed_summary"
            )
        yield _entry(
            "figure",
            {"group": "critical_speed", "name": "all"},
            figure("critical_speed", "all"),
            "critical_speed_summary",
        )


def _fe_entries(fe: Mapping) -> Iterator[Entry]:
    shows = figures_of(fe.get("paper_figures"))
    yield from fe_scene_entries(fe["scenes"], fe["readings"], shows)
    for name in list(fe.get("sweeps") or {}) + list(FE_STUDIES) + ["continuum_increments"]:
        yield _entry("fe_study", {"name": name}, fe_study(name), "fe_studies")
    for name in FE_SETUP_FITS:
        yield _entry("fe_study", {"name": name}, fe_study(name), "fe_setup_fit", shows.get(name, ()))
    for scene in (fe.get("comparison") or {}).get("claim_windows") or {}:
        yield _entry(
            "fe_continuum_window",
            {"scene": scene},
            fe_continuum_window(scene),
            "fe_continuum_window",
            shows.get(scene, ()),
        )
    for scene in fe["scenes"]:
        yield _entry(
            "fe_continuum", {"scene": scene}, fe_continuum(scene), "fe_model_comparison", shows.get(scene, ())
        )
        yield _entry("fe_deck", {"name": scene}, fe_deck(scene), "fe_decks")
        ccx = scene + FE_CCX_SUFFIX
        yield _entry("fe_deck", {"name": ccx}, fe_deck(ccx), "fe_decks")
        yield _entry(
            "figure", {"group": "fe", "name": scene}, figure("fe", scene), "fe_figures", shows.get(scene, ())
        )
    for ext in ("csv", "nc"):
        yield _entry("fe_model_comparison", {"ext": ext}, fe_model_comparison(ext), "fe_model_comparison")
        yield _entry("fe_peer_calculix", {"ext": ext}, fe_peer_calculix(ext), "fe_peer_calculix")
    for deck in FE_PEER_DECKS:
        yield _entry("fe_deck", {"name": deck}, fe_deck(deck), "fe_peer_calculix")
    yield _entry("fe_readings_claims", {}, fe_readings_claims(), "fe_readings_claims")
    for number in fe_paper_figure_numbers():
        yield _entry(
            "figure",
            {"group": "fe", "name": f"fig{number}"},
            figure("fe", f"fig{number}"),
            "fe_figures",
            (number,),
        )
    for name in ("readings", *FE_STUDIES):
        yield _entry("figure", {"group": "fe", "name": name}, figure("fe", name), "fe_figures")


def fe_paper_figure_numbers() -> range:
    """The paper's beam-on-disc figures, one PNG each (rule ``fe_figures``)."""
    return range(21, 37)


def fe_scene_entries(scenes: Iterable[str], readings: Iterable[str], shows=None) -> Iterator[Entry]:
    """Every FE scene under every FE reading, with its cross-scene ratios: what a claim re-read under another
    FE reading looks up (``claims.per_reading``) without the rest of the config."""
    shows = shows or {}
    for reading in readings:
        for scene in scenes:
            yield _entry(
                "fe_scene",
                {"reading": reading, "scene": scene},
                fe_scene(reading, scene),
                "fe_reading",
                shows.get(scene, ()),
            )
        yield _entry("fe_cross_scene", {"reading": reading}, fe_cross_scene(reading), "fe_reading")


def _study_entries(config: Mapping) -> Iterator[Entry]:
    for name in (config.get("dense_map") or {}).get("maps") or {}:
        yield _entry("dense_map", {"name": name}, dense_map(name), "dense_map_merge")
        yield _entry(
            "figure", {"group": "dense_map", "name": name}, figure("dense_map", name), "dense_map_figure"
        )
    methods = config.get("methods_study") or {}
    for scene in methods.get("scenes") or {}:
        yield _entry(
            "methods_work_precision",
            {"scene": scene},
            methods_work_precision(scene),
            "methods_work_precision",
        )
        yield _entry(
            "figure",
            {"group": "methods", "name": f"{scene}_work_precision"},
            figure("methods", f"{scene}_work_precision"),
            "methods_figures",
        )
    if methods:
        yield _entry("methods_failure_map", {}, methods_failure_map(), "methods_failure_map")
        yield _entry(
            "figure",
            {"group": "methods", "name": "failure_map"},
            figure("methods", "failure_map"),
            "methods_figures",
        )
        yield _entry(
            "notebook",
            {"name": "methods_work_precision"},
            notebook("methods_work_precision"),
            "methods_notebook",
        )
    validation = config.get("validation") or {}
    for law in validation.get("laws") or {}:
        yield _entry("validation_peer_table", {"law": law}, validation_peer_table(law), "validation_peer")
    for law in (validation.get("methods_per_law") or {}).get("laws") or []:
        yield _entry("validation_methods", {"law": law}, validation_methods(law), "validation_methods")
    if validation:
        yield _entry("validation_peer", {}, validation_peer(), "validation_peer")
        for ext in ("nc", "csv"):
            yield _entry(
                "validation_round_trip", {"ext": ext}, validation_round_trip(ext), "validation_round_trip"
            )
    inverse = config.get("inverse") or {}
    if inverse:
        for name in INVERSE_TABLES:
            yield _entry("inverse_table", {"name": name}, inverse_table(name), "inverse_study")
        for fig in [*inverse["figures"], "joint"]:
            yield _entry("inverse_dataset", {"figure": fig}, inverse_dataset(fig), "inverse_study")
        mode = "long" if inverse.get("long", False) else "default"
        for fig in inverse["settings"][mode].get("corner", []):
            for family in inverse["families"]:
                yield _entry(
                    "inverse_corner",
                    {"figure": fig, "family": family},
                    inverse_corner(fig, family),
                    "inverse_study",
                )


def _product_entries(config: Mapping) -> Iterator[Entry]:
    for ext in ("csv", "md"):
        yield _entry("claims_table", {"ext": ext}, claims_table(ext), "claims_table")
        yield _entry("benchmark_summary", {"ext": ext}, benchmark_summary(ext), "benchmark_summary")
    yield _entry("claims_check", {}, claims_check(), "claims_check")
    yield _entry("figure_verdicts", {}, figure_verdicts(), "figure_verdicts")
    for ext in ("csv", "nc"):
        yield _entry("reading_ranking", {"ext": ext}, reading_ranking(ext), "reading_ranking")
    yield _entry("unreproduced_claims", {}, unreproduced_claims(), "reading_ranking")
    for name in config.get("notebooks") or {}:
        yield _entry("notebook", {"name": name}, notebook(name), "render_notebooks")
    yield _entry("report_captions", {}, report_captions(), "report_captions")
    yield _entry("page", {}, page(), "replication_page")
    # the page's folders: thumbnails, each linked dataset's text preview, each linked source with line anchors
    for kind, folder in (
        ("page_thumbs", page_thumbs()),
        ("page_previews", page_previews()),
        ("page_source_pages", page_source_pages()),
    ):
        yield _entry(kind, {}, folder, "replication_page")


def catalogue(config: Mapping) -> dict[str, Entry]:
    """path -> Entry for every product the config makes (logs and benchmarks aside: every job has its
    own, named by ``log``/``benchmark``)."""
    entries = [
        *_onedof_entries(config["onedof"]),
        *(_fe_entries(config["fe"]) if config.get("fe") else ()),
        *_study_entries(config),
        *_product_entries(config),
    ]
    return {e.path: e for e in entries}


def showing(entries: Mapping[str, Entry], figure: int) -> list[Entry]:
    """The entries that show paper figure ``figure`` (their ``figures``), by path: its runs and images."""
    return sorted((e for e in entries.values() if figure in e.figures), key=lambda e: e.path)


def onedof_catalogue(onedof: Mapping) -> dict[str, Entry]:
    """dataset path -> Entry of every 1-DOF run (scene x reading x method) of the ``onedof`` section."""
    return {e.path: e for e in _onedof_entries(onedof) if e.kind == "onedof_dataset"}
