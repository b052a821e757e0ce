"""Where every dataset, table, figure, notebook, log and benchmark of the pipeline lives, declared once.

Each family of paths is a template (``onedof_dataset``, ``fe_scene``, ``figure``, ...), called as a function:
``fe_scene(reading, scene)``; called with wildcards, ``fe_scene("{fe_reading}", "{scene}")``, it is a rule's
output pattern. Rules, claims, notebooks, the page and the inverse study call these, and nothing else builds,
parses or rewrites a ``results/`` path (``tests/pipeline/test_catalogue.py`` greps).

``PRODUCTS`` declares each family of outputs once: its template, the rule that writes it, the rule's output
name, the config names it is expanded over and the key of the paper figures it shows. From it come both the
rules' outputs (``outputs(config, rule)``) and ``catalogue(config)``, every entry the config makes
(``config``: the typed ``stickslip.schema.PipelineConfig``, read by attribute, not imported): a path is
looked up, never parsed; a path that is not in it is no product of the pipeline, whatever it looks like. The
paper figures have one registry, the config's ``paper_figures`` maps (``paper_figures``).

At the bottom of the package: it imports nothing from the project, so every layer may use it.
"""

from __future__ import annotations

import inspect
import itertools
import string
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field

RESULTS = "results"


class PathTemplate:
    """A path function made from its template below ``results/``: the arguments fill its fields in the order
    they appear (or by name; ``defaults`` for the optional ones)."""

    def __init__(self, template: str, **defaults: str):
        self.template = template
        fields = [name for _, name, _, _ in string.Formatter().parse(template) if name]
        empty, kind = inspect.Parameter.empty, inspect.Parameter.POSITIONAL_OR_KEYWORD
        parameters = [inspect.Parameter(f, kind, default=defaults.get(f, empty)) for f in fields]
        self.__signature__ = inspect.Signature(parameters)
        self.__name__ = ""  # the module name it is bound to, set below its definitions

    def __call__(self, *args, **kwargs) -> str:
        bound = self.__signature__.bind(*args, **kwargs)
        bound.apply_defaults()
        return f"{RESULTS}/{self.template.format(**bound.arguments)}"

    def __repr__(self) -> str:
        return f"{self.__name__}{self.__signature__}"


# ------------------------------------------------------------------------------------------------- 1-DOF

#: The dataset of one 1-DOF run.
onedof_dataset = PathTemplate("onedof/{scene}/{reading}/{method}.nc")


def sweep_dataset(sweep: str, reading: str, dense: bool = False) -> str:
    """The dataset of one sweep for one reading, at the paper's values or dense."""
    return f"{RESULTS}/onedof/sweeps/{sweep}{'_dense' if dense else ''}/{reading}.nc"


#: Fig. 4: Eq. 6 as printed and the dimensionally correct curve.
eq6_curve = PathTemplate("onedof/fig04/eq6.nc")
#: Fig. 17: mu(v_r) along the baseline, ``csv`` (the FE scenes' friction law) or ``nc``.
friction_table = PathTemplate("onedof/friction_mu_vr.{ext}", ext="csv")
#: The continuation over belt speed for one reading, and every reading's critical speed (``csv`` or ``nc``).
critical_speed = PathTemplate("onedof/critical_speed/{reading}.nc")
critical_speed_summary = PathTemplate("onedof/critical_speed.{ext}", ext="csv")
#: One dense parameter map, every chunk merged, and one chunk (temporary: how many is decided at parse time).
dense_map = PathTemplate("dense_map/{name}.nc")
dense_map_chunk = PathTemplate("dense_map/chunks/{name}/{chunk}.nc")
#: The work-precision study of the integration methods on one scene, and the failure map.
methods_work_precision = PathTemplate("methods/{scene}_work_precision.nc")
methods_failure_map = PathTemplate("methods/failure_map.nc")
#: Switch solver vs CVODE for one friction law, and every law's.
validation_peer_table = PathTemplate("validation/peer_{law}.csv")
validation_peer = PathTemplate("validation/peer.nc")
#: The 1-DOF model driven by the Fig. 17 table, ``nc`` or ``csv``.
validation_round_trip = PathTemplate("validation/round_trip.{ext}", ext="nc")
#: The methods study on one nonlinear friction law.
validation_methods = PathTemplate("validation/methods_{law}.nc")

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

#: One paper scene under one FE reading, and the reading's cross-scene ratios.
fe_scene = PathTemplate("fe/{reading}/{scene}.nc")
fe_cross_scene = PathTemplate("fe/{reading}/cross_scene.nc")
#: A dataset shared by every FE reading: a sweep, ``convergence``, ``stability``, ``continuum_increments`` or
#: a setup fit.
fe_study = PathTemplate("fe/{name}.nc")
#: The continuum strip on one paper scene, and over a claim's window at dt and dt/2.
fe_continuum = PathTemplate("fe/continuum/{scene}.nc")
fe_continuum_window = PathTemplate("fe/continuum_window/{scene}.nc")
#: Continuum vs beam on every scene, ``csv`` or ``nc``.
fe_model_comparison = PathTemplate("fe/model_comparison.{ext}", ext="csv")
#: Every FE claim under every FE reading.
fe_readings_claims = PathTemplate("fe/readings_claims.csv")
#: CalculiX as a peer of the continuum strip, ``nc`` or ``csv``.
fe_peer_calculix = PathTemplate("fe/peer_calculix.{ext}", ext="nc")
#: An input deck: a scene for ABAQUS/Explicit or its CalculiX variant (``<scene>_ccx``), or a peer deck.
fe_deck = PathTemplate("fe/inp/{name}.inp")


def fe_paper_figure_numbers() -> range:
    """The paper's beam-on-disc figures: the ones the config's ``fe.paper_figures`` must map (the schema
    checks it) and the FE plots draw; which scenes each shows is the config's map."""
    return range(21, 37)


# ------------------------------------------------------------------------------------------------ inverse

INVERSE_TABLES = ("summary", "hypotheses", "ranking", "numbers", "conflicts")
#: One of ``INVERSE_TABLES``; the fit of one figure (or ``joint``); a corner plot.
inverse_table = PathTemplate("inverse/{name}.csv")
inverse_dataset = PathTemplate("inverse/{figure}.nc")
inverse_corner = PathTemplate("inverse/corner/{figure}_{family}.png")

# ------------------------------------------------------------------------------------------------- claims

#: Every claim vs what the pipeline measures, ``csv`` or ``md``, and the flag touched when every status is
#: its pin.
claims_table = PathTemplate("claims/deviations.{ext}", ext="csv")
claims_check = PathTemplate("claims/check.ok")
#: Every paper figure's verdicts.
figure_verdicts = PathTemplate("claims/figure_verdicts.csv")
#: The readings ranked by the claims they reproduce, ``csv`` or ``nc``, and the claims none reproduces.
reading_ranking = PathTemplate("claims/reading_ranking.{ext}", ext="csv")
unreproduced_claims = PathTemplate("claims/unreproduced_claims.csv")

# ----------------------------------------------------------------------------- figures, notebooks, page

#: A PNG: ``figure("fig02", reading)``, ``figure("fe", scene)``, ``figure("fe", "fig21")``,
#: ``figure("methods", "failure_map")``, ``figure("dense_map", name)``, ``figure("critical_speed", "all")``.
figure = PathTemplate("figures/{group}/{name}.png")
notebook = PathTemplate("notebooks/{name}.html")
report_captions = PathTemplate("report/captions.rst")
#: The replication page and its folders: thumbnails, each linked dataset's ``stickslip show`` text as HTML
#: (``<path below results>.html``).
page = PathTemplate("index.html")
page_thumbs = PathTemplate("page/thumbs")
page_previews = PathTemplate("page/datasets")
#: Wall time and peak memory of every job, per rule, ``csv`` or ``md``.
benchmark_summary = PathTemplate("benchmarks/summary.{ext}", ext="csv")

for _name, _template in list(globals().items()):
    if isinstance(_template, PathTemplate):
        _template.__name__ = _name  # the family's name: an Entry's kind
del _name, _template


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


def _get(value, key: str):
    """``key`` of a config value: an attribute of the typed config (``stickslip.schema``), or a mapping's
    entry (the few name lists a caller builds itself: ``onedof_catalogue``, ``fe_scene_entries``)."""
    return value.get(key) if isinstance(value, Mapping) else getattr(value, key, None)


def _in(key: str) -> Callable[[object], Iterable]:
    """Each name of the config value at dotted ``key`` (a mapping's keys, a list's items; none if missing)."""

    def names(config) -> Iterable:
        value = config
        for part in key.split("."):
            value = None if value is None else _get(value, part)
        return value or {}

    return names


@dataclass(frozen=True)
class Products:
    """One family of outputs: ``path`` filled with each of its ``names``, written by ``rule`` (a template over
    the names: ``simulate_onedof_{scene}``) as its output ``output`` (one output per product when the name is
    a template). A name is a constant, a tuple (each of them) or a function of the config (each it returns);
    ``figures``: the key of the paper figures it shows (``paper_figures``); ``when``: the config section it
    needs."""

    path: Callable[..., str]
    rule: str
    output: str
    #: key -> name(s), or a function of the config giving every product's names (names that depend on
    #: each other: a figure's readings)
    names: Mapping[str, object] | Callable[[object], Iterable[dict]] = field(default_factory=dict)
    figures: str = ""
    when: str = ""

    def expand(self, config) -> Iterator[dict]:
        """The names of every product the config makes, keyed in the path function's order."""
        if self.when and not _in(self.when)(config):
            return
        if callable(self.names):
            yield from self.names(config)
            return
        order = list(inspect.signature(self.path).parameters)
        keys = sorted(self.names, key=order.index)
        each = [self._each(self.names[k], config) for k in keys]
        for values in itertools.product(*each):
            yield dict(zip(keys, values))

    @staticmethod
    def _each(value, config) -> Iterable:
        return value if isinstance(value, tuple) else value(config) if callable(value) else (value,)

    def is_list(self, wildcards: Mapping) -> bool:
        """Whether the rule's output is a list: names vary that the rule's wildcards do not stand for."""
        if "{" in self.output:
            return False
        if callable(self.names):
            return True
        varying = {k for k, v in self.names.items() if isinstance(v, tuple) or callable(v)}
        return not varying <= set(wildcards)


def _per_reading(section: str) -> Callable[[object], list[dict]]:
    """group and name of each image of the 1-DOF config's figures ``section``: the figure, each reading."""
    return lambda c: [
        {"group": g, "name": r} for g, fig in _in(section)(c).items() for r in _get(fig, "readings")
    ]


_DENSE, _CSV_NC = (False, True), ("csv", "nc")
_FE_SCENES, _FE_READINGS = _in("fe.scenes"), _in("fe.readings")
_CRITICAL_READINGS, _METHODS_SCENES = _in("onedof.critical_speed.readings"), _in("methods_study.scenes")


def _ccx_decks(config) -> list[str]:
    return [scene + FE_CCX_SUFFIX for scene in _FE_SCENES(config)]


def _fe_paper_figures(config) -> list[str]:
    return [f"fig{number}" for number in sorted(_in("fe.paper_figures")(config))]


def _work_precision_charts(config) -> list[str]:
    return [f"{scene}_work_precision" for scene in _METHODS_SCENES(config)]


def _inverse_fits(config) -> list[str]:
    return [*_in("inverse.figures")(config), "joint"]


def _inverse_corners(config) -> list[str]:
    mode = "long" if _in("inverse.long")(config) else "default"
    return list(_in(f"inverse.settings.{mode}.corner")(config))


#: Every family of outputs, by section (names that depend on each other are listed whole: ``_per_reading``).
PRODUCTS = (
    # every run the config names; its rule writes those a figure, claim or notebook reads (onedof_runs)
    Products(onedof_dataset, "simulate_onedof_{scene}", "runs", figures="scene:{scene}",
             names={"scene": _in("onedof.scenes"), "reading": _in("onedof.readings"),
                    "method": _in("onedof.methods")}),
    Products(sweep_dataset, "onedof_sweeps", "sweeps", figures="sweep:{sweep}",
             names={"sweep": _in("onedof.sweeps"), "reading": _in("onedof.readings"), "dense": _DENSE}),
    Products(eq6_curve, "eq6_curve", "nc", figures="eq6"),
    Products(figure, "eq6_curve", "png", {"group": "fig04", "name": "eq6"}, figures="eq6"),
    Products(friction_table, "friction_table", "{ext}", {"ext": _CSV_NC}),
    Products(figure, "onedof_figure_{group}", "figures", _per_reading("onedof.figures"), "figure:{group}"),
    Products(figure, "sweep_figure_{group}", "figures", _per_reading("onedof.sweep_figures"),
             "figure:{group}"),
    Products(critical_speed, "critical_speed", "datasets", {"reading": _CRITICAL_READINGS}),
    Products(critical_speed_summary, "critical_speed_summary", "{ext}", {"ext": _CSV_NC},
             when="onedof.critical_speed"),
    Products(figure, "critical_speed_summary", "png", {"group": "critical_speed", "name": "all"},
             when="onedof.critical_speed"),
    # beam on disc
    Products(fe_scene, "fe_reading", "scenes", {"reading": _FE_READINGS, "scene": _FE_SCENES}, "fe:{scene}"),
    Products(fe_cross_scene, "fe_reading", "cross", {"reading": _FE_READINGS}),
    Products(fe_study, "fe_studies", "sweeps", {"name": _in("fe.sweeps")}, when="fe"),
    Products(fe_study, "fe_studies", "{name}", {"name": FE_STUDIES}, when="fe"),
    Products(fe_study, "fe_studies", "increments", {"name": "continuum_increments"}, when="fe"),
    Products(fe_study, "fe_setup_fit", "fit", {"name": tuple(FE_SETUP_FITS)}, "fe:{name}", when="fe"),
    Products(fe_continuum_window, "fe_continuum_window", "window",
             {"scene": _in("fe.comparison.claim_windows")}, "fe:{scene}"),
    Products(fe_continuum, "fe_model_comparison", "continuum", {"scene": _FE_SCENES}, "fe:{scene}"),
    Products(fe_model_comparison, "fe_model_comparison", "table", {"ext": "csv"}, when="fe"),
    Products(fe_model_comparison, "fe_model_comparison", "dataset", {"ext": "nc"}, when="fe"),
    Products(fe_readings_claims, "fe_readings_claims", "table", when="fe"),
    Products(fe_deck, "fe_decks", "decks", {"name": _FE_SCENES}),
    Products(fe_deck, "fe_decks", "ccx_decks", {"name": _ccx_decks}),
    Products(fe_peer_calculix, "fe_peer_calculix", "dataset", {"ext": "nc"}, when="fe"),
    Products(fe_peer_calculix, "fe_peer_calculix", "table", {"ext": "csv"}, when="fe"),
    Products(fe_deck, "fe_peer_calculix", "decks", {"name": FE_PEER_DECKS}, when="fe"),
    Products(figure, "fe_figures", "scenes", {"group": "fe", "name": _FE_SCENES}, "fe:{name}"),
    Products(figure, "fe_figures", "paper", {"group": "fe", "name": _fe_paper_figures}, "fe:{name}"),
    Products(figure, "fe_figures", "{name}", {"group": "fe", "name": ("readings", *FE_STUDIES)}, when="fe"),
    # studies
    Products(dense_map, "dense_map_merge", "map", {"name": _in("dense_map.maps")}),
    Products(figure, "dense_map_figure", "png", {"group": "dense_map", "name": _in("dense_map.maps")}),
    Products(methods_work_precision, "methods_work_precision", "dataset", {"scene": _METHODS_SCENES}),
    Products(methods_failure_map, "methods_failure_map", "dataset", when="methods_study"),
    Products(figure, "methods_figures", "work_precision",
             {"group": "methods", "name": _work_precision_charts}),
    Products(figure, "methods_figures", "failure_map", {"group": "methods", "name": "failure_map"},
             when="methods_study"),
    Products(notebook, "methods_notebook", "notebook", {"name": "methods_work_precision"},
             when="methods_study"),
    Products(validation_peer_table, "validation_peer", "csv", {"law": _in("validation.laws")}),
    Products(validation_peer, "validation_peer", "nc", when="validation"),
    Products(validation_round_trip, "validation_round_trip", "{ext}", {"ext": ("nc", "csv")},
             when="validation"),
    Products(validation_methods, "validation_methods", "datasets",
             {"law": _in("validation.methods_per_law.laws")}),
    Products(inverse_table, "inverse_study", "{name}", {"name": INVERSE_TABLES}, when="inverse"),
    Products(inverse_dataset, "inverse_study", "datasets", {"figure": _inverse_fits}, when="inverse"),
    Products(inverse_corner, "inverse_study", "corner",
             {"figure": _inverse_corners, "family": _in("inverse.families")}),
    # the products of the products
    Products(claims_table, "claims_table", "{ext}", {"ext": ("csv", "md")}),
    Products(claims_check, "claims_check", "flag"),
    Products(figure_verdicts, "figure_verdicts", "table"),
    Products(reading_ranking, "reading_ranking", "{ext}", {"ext": _CSV_NC}),
    Products(unreproduced_claims, "reading_ranking", "unreproduced"),
    Products(notebook, "render_notebooks", "notebooks", {"name": _in("notebooks")}),
    Products(report_captions, "report_captions", "captions"),
    Products(page, "replication_page", "html"),
    Products(page_thumbs, "replication_page", "thumbs"),
    Products(page_previews, "replication_page", "previews"),
    Products(benchmark_summary, "benchmark_summary", "{ext}", {"ext": ("csv", "md")}),
)  # fmt: skip


def paper_figures(config) -> dict[str, tuple[int, ...]]:
    """The paper figures each product shows, from the config's ``paper_figures`` maps (the one registry):
    ``figure:<1-DOF figure>``, the runs drawn in them (``scene:<scene>``, ``sweep:<sweep>``), ``eq6``, and
    ``fe:<scene>`` and ``fe:fig<n>`` from ``fe.paper_figures`` (figure -> scenes)."""
    out: dict[str, set[int]] = {"eq6": set(_in("onedof.eq6.paper_figures")(config))}
    for section, run in (("figures", "scene"), ("sweep_figures", "sweep")):
        for name, spec in _in(f"onedof.{section}")(config).items():
            for key in (f"figure:{name}", f"{run}:{_get(spec, run)}"):
                out.setdefault(key, set()).update(_get(spec, "paper_figures") or ())
    for number, scenes in _in("fe.paper_figures")(config).items():
        for key in (f"fe:fig{number}", *(f"fe:{scene}" for scene in scenes)):
            out.setdefault(key, set()).add(int(number))
    return {key: tuple(sorted(numbers)) for key, numbers in out.items()}


def catalogue(config) -> dict[str, Entry]:
    """path -> Entry for every product the config makes (logs and benchmarks aside: every job has its
    own, named by ``log``/``benchmark``)."""
    shows = paper_figures(config)
    entries = {}
    for products in PRODUCTS:
        for names in products.expand(config):
            path = products.path(**names)
            figures = shows.get(products.figures.format(**names), ()) if products.figures else ()
            pairs = tuple((key, str(value)) for key, value in names.items())
            entries[path] = Entry(products.path.__name__, pairs, path, products.rule.format(**names), figures)
    return entries


def outputs(config, rule: str, **wildcards: str) -> dict[str, str | list[str]]:
    """A rule's outputs, named and ordered as its script reads them: every product ``rule`` writes, each name
    in ``wildcards`` replaced by the rule's wildcard (``reading="{fe_reading}"``)."""
    out: dict[str, str | list[str]] = {}
    for products in PRODUCTS:
        if not rule.startswith(products.rule.split("{")[0]):
            continue  # not the rule's: skipped without expanding it
        for names in products.expand(config):
            if products.rule.format(**names) != rule:
                continue
            names.update((key, value) for key, value in wildcards.items() if key in names)
            path, output = products.path(**names), products.output.format(**names)
            if not products.is_list(wildcards):
                out[output] = path
            elif path not in out.setdefault(output, []):
                out[output].append(path)
    return out


def same_entry(entries: Mapping[str, Entry], entry: Entry, **names: str) -> Entry | None:
    """The entry of the same kind as ``entry`` whose names are ``entry``'s with ``names`` changed (the same
    FE scene in another reading: ``same_entry(cat, e, reading="node1_upper")``); None if there is none."""
    wanted = tuple((k, names.get(k, v)) for k, v in entry.names)
    return next((e for e in entries.values() if e.kind == entry.kind and e.names == wanted), None)


def showing(entries: Mapping[str, Entry], figure: int) -> list[Entry]:
    """The entries that show paper figure ``figure`` (their ``figures``), by path: its runs and images."""
    return sorted((e for e in entries.values() if figure in e.figures), key=lambda e: e.path)


def _of_kinds(config, *kinds: str) -> dict[str, Entry]:
    return {path: e for path, e in catalogue(config).items() if e.kind in kinds}


def onedof_catalogue(onedof) -> dict[str, Entry]:
    """dataset path -> Entry of every 1-DOF run (scene x reading x method) of the ``onedof`` section."""
    return _of_kinds({"onedof": onedof}, "onedof_dataset")


def fe_scene_entries(scenes: Iterable[str], readings: Iterable[str]) -> Iterator[Entry]:
    """Every FE scene under every FE reading, with its cross-scene ratios: what a claim re-read under another
    FE reading looks up (``claims.per_reading``) without the rest of the config."""
    fe = {"scenes": list(scenes), "readings": list(readings)}
    yield from _of_kinds({"fe": fe}, "fe_scene", "fe_cross_scene").values()
