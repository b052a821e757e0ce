"""The ``stickslip`` console command: your own scenario, a figure's claims, a dataset's summary.

    stickslip run --mu-s 0.6 --damping 1.0            one 1-DOF run against the baseline and the paper
    stickslip run --scene fig06 --json                 a figure's scene, its metrics as JSON
    stickslip run --law stribeck mu_k=0.3 v_s=0.5      any friction law (switch solver)
    stickslip laws                                     the friction laws: parameters, formulas, units
    stickslip fe --scene section9_kinematic --speed 2 --t-end 0.1 -o s9.nc
    stickslip claims --figure 2                        the figure's claims, verdict and reasons
    stickslip show results/onedof/fig02/consistent_caption/exact.nc

Runs from any folder: project paths (config, claims, the friction table, results) are the project's the
package belongs to, or --root's; paths you give (-o, --plot, --json, --csv, show FILE) are yours, relative to
the working directory. Options are checked as config keys (the typed models of
``stickslip.schema``): a bad value is reported with the option and the config key it sets,
before any work, as are output paths (never the pipeline's results folder) and the run's cost (the
pipeline's cost guard). ``-o`` writes the dataset the pipeline would write (``stickslip.api``), ``--plot`` the
pipeline's figure of it. Exit status: 0 an answer (a diverging model is one), 1 a numerical failure or a
damaged dataset, 2 bad input.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING

from . import catalogue as paths

if TYPE_CHECKING:  # annotations only: pydantic is imported when a command reads the config
    from .schema import Onedof

#: The paper's metrics ``stickslip run`` prints (dataset variables), each with its definition: the table's
#: footnotes and ``stickslip run --help`` print these, so no number is shown undefined.
DEFINITIONS = {
    "amplitude_peak_to_peak": "max x - min x over the steady window (t >= transient): the swing of the "
    "displacement x [mm] from its lowest to its highest point",
    "amplitude_peak_to_zero": "max |x| over the steady window: the largest excursion from x = 0, where the "
    "spring is unstretched. An oscillation about an offset centre has peak-to-zero above half its "
    "peak-to-peak, and above the whole peak-to-peak when it never crosses x = 0",
    "frequency_peaks": "1 / (mean spacing of the displacement maxima) in the steady window [Hz], as the "
    "paper counts peaks",
    "stick_time": "mean duration of the complete stick intervals (mass moving with the belt, v_r = 0) in "
    "the steady window [s]",
    "slip_time": "mean duration of the complete slip intervals (v_r != 0) in the steady window [s]",
    "first_stick_time": "duration of the first stick interval from t = 0 [s]: defined even for a run that "
    "later diverges",
}
METRICS = tuple(DEFINITIONS)
#: Config keys of the API's own arguments whose option is not ``--<key>``.
OPTION_OF_KEY = {"output": "-o/--output", "ensemble.seeds": "--ensemble (ensemble.seeds)"}
#: The API's own arguments, each set by its option ``--<key>``.
API_KEYS = ("root", "speed", "rpm", "t_end", "model", "plot", "json", "csv", "scene", "reading", "method")


class UsageError(Exception):
    """A bad option: the message names it (and the config key it sets)."""


def _option(key: str) -> str:
    return OPTION_OF_KEY.get(key) or "--" + key.replace("_", "-")


def run_options() -> dict[str, str]:
    """The options of a 1-DOF scene's parameters (``onedof.scenes.<scene>.params.<key>``) and run lengths
    (``onedof.scenes.<scene>.<key>``) -> their meaning, as the typed config describes them."""
    from .schema import BeltParameters, RunLengths

    fields = {**BeltParameters.model_fields, **RunLengths.model_fields}
    return {k: f.description for k, f in fields.items() if k not in ("units", "count_window")}


def _as_option(message: str) -> str:
    """A config error's message with the option that set the key in front of it."""
    for line in message.splitlines():
        key, _, why = line.partition(":")
        why = why.strip()
        if key in OPTION_OF_KEY or key in API_KEYS:
            return f"{_option(key)}: {why}"
        if key.startswith("fe.scenes."):
            return f"--scene: {line}"
        if key.startswith("onedof.scenes.") and key.endswith(".law derivative"):
            return f"law_derivative ({key}): {why}"
        if ".law" in key:
            either = "/--method" if "'switch' solver only" in line else ""
            return f"--law{either} ({key}): {why}"
        if key.rsplit(".", 1)[-1] in run_options():
            return f"{_option(key.rsplit('.', 1)[-1])} ({key}): {why}"
    return message


def _law(values: list[str] | None) -> dict | None:
    """``--law KIND key=value ...`` as a config law mapping (numbers as numbers, a table's path as text)."""
    if not values:
        return None
    entry: dict = {"kind": values[0]}
    for item in values[1:]:
        key, sep, value = item.partition("=")
        if not sep or not key:
            raise UsageError(f"--law: expected KEY=VALUE after the kind, got {item!r}")
        try:
            entry[key] = float(value) if key != "path" else value
        except ValueError:
            raise UsageError(f"--law {key}: expected a number, got {value!r}") from None
    return entry


def _common(parser: argparse.ArgumentParser, root_help: str, outputs: bool = True) -> None:
    parser.add_argument("--root", type=Path, help=root_help)
    if not outputs:
        return
    parser.add_argument(
        "--configfile",
        action="append",
        default=[],
        metavar="FILE",
        help="config overlay over config/*.yaml (as snakemake --configfile); repeatable",
    )
    parser.add_argument(
        "-o",
        "--output",
        type=Path,
        help="write the dataset (netCDF) the pipeline would write; never into the pipeline's results folder",
    )
    parser.add_argument("--plot", type=Path, help="draw the pipeline's figure of the run to this PNG")
    parser.add_argument(
        "--force", action="store_true", help="overwrite an existing -o/--plot file (never one under results/)"
    )


ROOT_HELP = "project folder (default: the checkout the package belongs to, or the cwd)"


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stickslip", description=__doc__.split("\n\n")[0], formatter_class=argparse.RawTextHelpFormatter
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    run = sub.add_parser(
        "run",
        help="one 1-DOF run: the paper's metrics against the baseline and the paper",
        description="One 1-DOF run (mass on a moving belt): first its outcome (stick-slip, no stick, rest, "
        "diverged with the mechanism, or a numerical failure), then amplitude, frequency, stick and slip "
        "time next to the baseline's and the paper's values for the scene's figure (--scene figNN: that "
        "figure's claims). Parameters not given are the scene's. Exit 0 for an answer (a diverging model is "
        "one), 1 for a numerical failure, 2 for bad input.",
        epilog="metrics (dataset variables):\n"
        + "\n".join(f"  {name}: {text}" for name, text in DEFINITIONS.items()),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    run.add_argument("--scene", help="base scene (onedof.scenes; default: the baseline's)")
    run.add_argument("--reading", help="reading of the paper's friction (onedof.readings)")
    run.add_argument("--method", help="integration method (onedof.methods; default exact, switch with --law)")
    for key, text in run_options().items():
        metavar = "S" if key in ("t_end", "output_dt", "transient") else "X"
        run.add_argument(_option(key), dest=key, type=float, metavar=metavar, help=text)
    run.add_argument("--units", choices=["as_given", "si"], help="how the parameters' units are read")
    run.add_argument(
        "--law",
        nargs="+",
        metavar=("KIND", "KEY=VALUE"),
        help="friction law replacing the reading's: affine, coulomb, stribeck, rational, tabulated, then "
        "its parameters (mu_s defaults to the run's), e.g. --law stribeck mu_k=0.3 v_s=0.5",
    )
    run.add_argument("--ensemble", action="store_true", help="add the config's perturbation ensemble")
    for key, text in (
        ("--json", "the outcome and metrics as JSON to FILE (no FILE: to stdout, instead of the table)"),
        (
            "--csv",
            "the metrics as CSV (metric,value,units,baseline,paper,claims,definition) to FILE or stdout",
        ),
    ):
        run.add_argument(key, nargs="?", const="-", metavar="FILE", help=f"write {text}")
    _common(run, ROOT_HELP)

    fe = sub.add_parser(
        "fe",
        help="one beam-on-disc scene, with progress lines",
        description="One beam-on-disc scene as rule fe_reading computes it (perturbation ensemble and "
        "step-halving check included unless --no-ensemble).",
    )
    fe.add_argument("--scene", required=True, help="fe.scenes name, or its stem with --speed or --rpm")
    fe.add_argument(
        "--speed",
        type=float,
        metavar="MM_S",
        help="disc surface speed [mm/s], any value > 0 (0.5 is the configured _0p5mm_s scene; another "
        "runs the stem's scene at that speed)",
    )
    fe.add_argument("--rpm", type=float, metavar="N", help="disc speed [rev/min] instead of --speed")
    fe.add_argument("--reading", help="FE reading (fe.readings; default: the first)")
    fe.add_argument("--model", choices=["beam", "continuum"], default="beam", help="FE model (default beam)")
    fe.add_argument("--t-end", dest="t_end", type=float, metavar="S", help="simulated window [s]")
    fe.add_argument("--no-ensemble", dest="ensemble", action="store_false", help="the base run only")
    _common(fe, ROOT_HELP)

    claims = sub.add_parser(
        "claims",
        help="a paper figure's claims, verdict and reasons (after a build)",
        description=f"Reads {paths.claims_table()} (rule claims_table) and the claims files.",
    )
    claims.add_argument("--figure", type=int, required=True, help="paper figure number")
    claims.add_argument("--reading", help="show this reading (default: the figure's best)")
    _common(claims, "project folder", outputs=False)

    laws = sub.add_parser(
        "laws",
        help="the friction laws --law takes: parameters, formulas, units",
        description="Every kind of stickslip.model.laws: its formula, its parameters with units and "
        "defaults. From Python, simulate(law=...) also takes any callable mu(v_r) (law_derivative= its "
        "derivative) or FrictionLaw subclass, checked as the built-in laws are.",
    )
    laws.add_argument("--json", action="store_true", help="print the list as JSON")

    show = sub.add_parser(
        "show",
        help="readable summary of a result dataset",
        description="Title, provenance, scalar results with units, arrays and the checksum state of a "
        "dataset. Exit 0: checksum ok; 1: the content no longer matches its checksum; 2: not a dataset.",
    )
    show.add_argument(
        "file",
        type=Path,
        help="a netCDF dataset the pipeline or this command wrote (a path not found here is looked up in "
        "the project folder, so results/... works from anywhere)",
    )
    _common(show, "project folder for a results/... path", outputs=False)
    return parser


# -- run -------------------------------------------------------------------------------------------------


def _fmt(value, unit: str = "") -> str:
    if value is None or value != value:
        return "n/a"
    return f"{value:.4g}" + (f" {unit}" if unit else "")


def _metrics(ds) -> dict:
    return {m: float(ds[m]) for m in METRICS if m in ds and ds[m].ndim == 0}


def baseline_metrics(onedof: Onedof, reading: str, root: Path) -> tuple[dict, str]:
    """The baseline's metrics in ``reading``: from the build when its dataset exists, else computed."""
    from .io.netcdf import read_dataset

    base = onedof.baseline
    path = root / paths.onedof_dataset(base.scene, reading, base.method)
    if path.is_file():
        return _metrics(read_dataset(path)), str(path.relative_to(root))
    from .studies.onedof import scene_run_dataset
    from .studies.specs import baseline_spec

    return _metrics(scene_run_dataset(baseline_spec(onedof, reading))), "computed"


def paper_values(onedof: Onedof, root: Path, scene: str | None = None) -> dict[str, list[tuple[float, str]]]:
    """The paper's numbers for a scene (default: the baseline's): every ``value`` claim on its dataset, so
    ``--scene fig06`` is compared with Fig. 6's numbers, not Fig. 2's."""
    from .claims.load import load_claims

    base = onedof.baseline
    target = paths.onedof_dataset(scene or base.scene, "{reading}", base.method)
    # read (and check) only the files with a claim on the baseline's dataset: the run waits for no others
    files = [p for p in sorted((root / "config" / "claims").glob("*.yaml")) if target in p.read_text()]
    out: dict[str, list[tuple[float, str]]] = {}
    for row in load_claims(files):
        if row.kind == "value" and row.dataset == target and row.variable in METRICS:
            out.setdefault(row.variable, []).append((row.value, row.id))
    return out


def _number(value):
    """A JSON/CSV number: None for NaN or a missing value."""
    return None if value is None or value != value else float(value)


def run_report(ds, reading: str, base: dict, where: str, paper: dict) -> dict:
    """The run's outcome and metrics as data: what --json writes and the table prints."""
    from .analysis.metrics import metric_attrs

    mine = _metrics(ds)
    message = ds.attrs.get("message", "")
    outcome, _, mechanism = message.partition(": ")  # the outcome's flag name (spaced) and its mechanism
    return {
        "title": ds.attrs.get("title", "").strip(),
        "scene": ds.attrs.get("scene_name", ""),
        "description": ds.attrs.get("scene_description", ""),
        "reading": reading,
        "method": ds.attrs.get("method_name", ""),
        "status": ds.attrs.get("status", ""),
        "success": int(ds.attrs.get("success", 0)),
        "message": message,
        "outcome": outcome.replace(" ", "_"),
        "mechanism": mechanism,
        "solver": ds.attrs.get("solver_message", ""),
        "baseline_source": where,
        "metrics": {
            m: {
                "value": _number(mine.get(m)),
                "units": metric_attrs(m)["units"],
                "baseline": _number(base.get(m)),
                "paper": [{"value": v, "claim": cid} for v, cid in paper.get(m, [])],
                "definition": DEFINITIONS[m],
            }
            for m in METRICS
        },
    }


def _csv_text(report: dict) -> str:
    import csv
    import io

    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["metric", "value", "units", "baseline", "paper", "claims", "definition"])
    for name, m in report["metrics"].items():
        value, base = ("" if x is None else repr(x) for x in (m["value"], m["baseline"]))
        paper = ";".join(repr(p["value"]) for p in m["paper"])
        claims = ";".join(p["claim"] for p in m["paper"])
        writer.writerow([name, value, m["units"], base, paper, claims, m["definition"]])
    return buf.getvalue()


def print_run(report: dict, out=None) -> None:
    """The outcome block first (the answer and why), then the metrics table, then what each metric is."""
    out = out or sys.stdout
    why = report["mechanism"] or report["message"]
    print(f"outcome: {report['outcome'].replace('_', ' ')}: {why}", file=out)
    print(f"{report['title']}", file=out)
    print(f"  {report['description']}; solver: {report['solver']}", file=out)
    rows = [("metric", "this run", f"baseline ({report['baseline_source']})", "paper (claim)")]
    for name, m in report["metrics"].items():
        unit = m["units"]
        reported = "; ".join(f"{_fmt(p['value'], unit)} ({p['claim']})" for p in m["paper"]) or "-"
        rows.append((name, _fmt(m["value"], unit), _fmt(m["baseline"], unit), reported))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for row in rows:
        print("  " + "  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip(), file=out)
    if any(m["value"] is None for m in report["metrics"].values()):
        print(
            f"  n/a: not defined by this run, whose outcome is {report['outcome'].replace('_', ' ')}",
            file=out,
        )
    print("  metrics (steady window: t >= the scene's transient):", file=out)
    for name, text in DEFINITIONS.items():
        print(f"    {name}: {text}", file=out)


def _project(args, keys=("output", "plot", "json", "csv")) -> tuple[Path, dict]:
    """(project folder, config) of a command that writes files, every file it will write checked before any
    work (``api.check_output``)."""
    from . import api

    root = api.project_root(args.root)
    config = api.load_project_config(args.configfile, root)
    seen = set()
    for key in keys:
        value = getattr(args, key, None)
        if value is None or str(value) == "-":
            continue
        path = Path(value).expanduser().resolve()
        if path in seen:
            raise UsageError(f"{_option(key)}: {value} is also another option's output")
        seen.add(path)
        api.check_output(value, force=args.force, key=key, config=config)
    if [getattr(args, k, None) for k in ("json", "csv")] == ["-", "-"]:
        raise UsageError("--json/--csv: only one of them can go to stdout; give the other a FILE")
    return root, config


def _wrote(target, out) -> None:
    if target and str(target) != "-":
        print(f"wrote {target}", file=out)


def _save(fig, path: Path, dpi: int, out) -> None:
    """Save a figure drawn with matplotlib's file backend, then close it."""
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    _wrote(path, out)


def cmd_run(args) -> int:
    from . import api

    started = time.perf_counter()
    values = {k: getattr(args, k) for k in [*run_options(), "units"] if getattr(args, k) is not None}
    values |= {k: getattr(args, k) for k in ("reading", "method", "ensemble", "output", "force")}
    law = _law(args.law)
    root, config = _project(args)
    ds = api.simulate(args.scene, law=law, root=root, config=config, **values)
    onedof = api.onedof_project(config).onedof
    reading = args.reading or onedof.baseline.reading
    base, where = baseline_metrics(onedof, reading, root)
    report = run_report(ds, reading, base, where, paper_values(onedof, root, args.scene))
    # with --json or --csv on stdout, stdout is the data: the text goes to stderr
    text_out = sys.stderr if "-" in (args.json, args.csv) else sys.stdout
    print_run(report, text_out)
    if args.output:
        report["output"] = str(args.output)
    _wrote(args.output, text_out)
    if args.plot:
        _plot_onedof(ds, onedof, args.plot, reading, text_out)
    for target, text in ((args.json, lambda r: json.dumps(r, indent=1) + "\n"), (args.csv, _csv_text)):
        if target:
            (sys.stdout.write if target == "-" else Path(target).write_text)(text(report))
            _wrote(target, text_out)
    print(f"({time.perf_counter() - started:.1f} s)", file=text_out)
    return 0 if report["status"] != "failed" else 1  # a divergence is an answer; a failure is not


def _plot_onedof(ds, onedof: Onedof, path: Path, reading: str, out) -> None:
    import matplotlib

    matplotlib.use("Agg")
    from .presentation.plots import onedof_figure
    from .schema import Figure

    scene = ds.attrs.get("scene_name", "")
    drawn_as = next(({"plot": f.plot} for f in onedof.figures.values() if f.scene == scene), {})
    method = ds.attrs.get("method_name", "")
    # the figure adds the reading under the title: the title names the run and its friction law, once each
    law = ds.attrs.get("scene_friction_law")
    friction = f", friction law {law}" if law else ""
    title = f"{ds.attrs.get('scene_figure', '')} {scene}: method {method}{friction}".strip()
    spec = Figure(title=title, scene=scene, readings=[reading], methods=[method], **drawn_as)
    _save(onedof_figure({method: ds}, spec, reading=reading), path, 110, out)


# -- fe --------------------------------------------------------------------------------------------------


def cmd_fe(args) -> int:
    from . import api
    from .io.progress import Progress
    from .presentation.show import summary_text

    started = time.perf_counter()
    announced = []

    def progress(label):
        if not announced:  # once the run starts: a refused input is answered before any "running"
            announced.append(label)
            note = f"running {args.scene} ({args.model}); progress every 2 s on stderr"
            print(note, file=sys.stderr, flush=True)
        return Progress(label, every=2.0, sink=lambda line: print(line, file=sys.stderr, flush=True))

    root, _ = _project(args, keys=("output", "plot"))
    given = ("speed", "rpm", "reading", "model", "t_end", "ensemble", "output", "force")
    options = {k: getattr(args, k) for k in given}
    ds = api.simulate_fe(args.scene, progress=progress, configfiles=args.configfile, root=root, **options)
    print(summary_text(ds))
    _wrote(args.output, sys.stdout)
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        from .presentation.fe_plots import fe_scene_figure

        _save(fe_scene_figure(ds, None, title=ds.attrs.get("title", "")), args.plot, 100, sys.stdout)
    print(f"({time.perf_counter() - started:.1f} s)")
    return 0


# -- laws ------------------------------------------------------------------------------------------------

#: Units and meaning of every law parameter (``stickslip.model.laws``).
LAW_PARAMETERS = {
    "mu_s": ("1", "static friction coefficient: the largest |F|/N in stick (default: the run's mu_s)"),
    "mu_k": ("1", "kinetic coefficient: the slip limit at high relative speed"),
    "sigma": ("s/mm", "slope of the affine law"),
    "plateau_speed": ("mm/s", "relative speed beyond which the affine law stays constant (default: none)"),
    "v_s": ("mm/s", "Stribeck speed: mu falls by 1/e of mu_s - mu_k over it"),
    "delta": ("s/mm", "rate of the rational fall"),
    "path": ("file", "CSV (relative_speed [mm/s], mu; one header line) or netCDF (mu over relative_speed)"),
    "static_mu": ("1", "static limit of a table (default: its first row)"),
}


def law_kinds() -> list[dict]:
    """Every law kind: formula, parameters (units, meaning, required or default)."""
    import dataclasses

    from .model.laws import _LAW_KEYS, LAW_KINDS

    out = []
    for kind, cls in LAW_KINDS.items():
        doc = (cls.__doc__ or "").strip().split("\n\n")[0].replace("\n", " ")
        defaults = {
            f.name: f.default for f in dataclasses.fields(cls) if f.default is not dataclasses.MISSING
        }
        params = []
        for name in sorted(_LAW_KEYS[kind], key=list(LAW_PARAMETERS).index):
            units, text = LAW_PARAMETERS[name]
            if name in defaults:
                default = defaults[name]
                required = "optional" if default is None else f"default {default}"
            else:
                required = "optional" if name in ("mu_s", "static_mu") else "required"
            params.append({"name": name, "units": units, "meaning": text, "required": required})
        out.append({"kind": kind, "formula": doc, "parameters": params})
    out.append(
        {
            "kind": "callable (Python only)",
            "formula": "simulate(law=mu) with mu(v_r) -> float of the relative speed |v_r| >= 0 [mm/s]; "
            "law_derivative=dmu optional; static limit mu(0)",
            "parameters": [],
        }
    )
    return out


def cmd_laws(args) -> int:
    kinds = law_kinds()
    if args.json:
        print(json.dumps(kinds, indent=1))
        return 0
    print(
        "Friction laws (--law KIND KEY=VALUE ...; slip force F = -N mu(|v_r|) sgn(v_r), "
        "|F| <= N mu_s in stick)"
    )
    for entry in kinds:
        print(f"{entry['kind']}: {entry['formula']}")
        for prm in entry["parameters"]:
            print(f"    {prm['name']} [{prm['units']}] ({prm['required']}): {prm['meaning']}")
    print("e.g. stickslip run --law stribeck mu_k=0.3 v_s=0.5 (the switch solver integrates every law)")
    return 0


# -- claims ----------------------------------------------------------------------------------------------


def _rounded(text: str) -> str:
    """A number of the claims table to 4 significant digits (the table keeps every digit); text as it is."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return text
    return f"{value:.4g}" if value == value else "n/a"


def cmd_claims(args) -> int:
    from . import api
    from .claims.load import load_claims
    from .claims.table import read_table
    from .claims.verdicts import VERDICT_RULE, is_evidence, rows_in_reading, tally

    root = api.project_root(args.root)
    table = root / paths.claims_table()
    if not table.is_file():
        raise UsageError(
            f"--figure: {table} does not exist: build the claims table first "
            f"(`make figures`, or `.venv/bin/snakemake -j2 {paths.claims_table()}`)"
        )
    claims = load_claims(sorted((root / "config" / "claims").glob("*.yaml")))
    ids = {row.id for row in claims if args.figure in row.figures}
    if not ids:
        raise UsageError(f"--figure: no claim of config/claims/*.yaml is about Fig. {args.figure}")
    rows = [r for r in read_table(table) if r["claim"] in ids]
    config = api.load_project_config((), root)
    primary = api.onedof_project(config).claims.primary_reading
    # the primary reading (declared in docs/READINGS.md) unless the user asks for another
    reading = args.reading or (primary if any(r["reading"] for r in rows) else "")
    shown = rows_in_reading(rows, reading)
    t = tally(shown)
    which = "the primary reading" if not args.reading else "reading"
    print(
        f"Fig. {args.figure}: {t.label}, {t.text} decided claims reproduced in {which} {reading or '(any)'}"
        f" ({VERDICT_RULE[t.label]}); {t.undecided} undecided, {t.apart} not evidence (listed, not counted)"
    )
    for r in sorted(shown, key=lambda r: (not is_evidence(r), r["claim"])):
        apart = "" if is_evidence(r) else f"  [{r['evidence'].replace('_', ' ')}: not counted]"
        print(
            f"- {r['claim']}: {r['status']}{apart}  reported {_rounded(r['reported'])}"
            f"{' ' + r['unit'] if r['unit'] else ''}, "
            f"measured {_rounded(r['measured'])}"
        )
        print(f'    "{r["quote"]}"')
        if r["reason"]:
            print(f"    reason: {r['reason']}")
    made = paths.showing(paths.catalogue(config), args.figure)
    if made:
        print(f"Runs and images of Fig. {args.figure} (stickslip.catalogue; `snakemake -n PATH`: its job):")
        for entry in made:
            print(f"  {entry.path}  (rule {entry.rule})")
    return 0


# -- show ------------------------------------------------------------------------------------------------


def cmd_show(args) -> int:
    from . import api
    from .presentation.show import show_state

    path = args.file
    if not path.exists() and not path.is_absolute():  # results/... as the docs show it, from anywhere
        in_project = api.project_root(args.root) / path
        path = in_project if in_project.exists() else path
    if not path.is_file():
        raise UsageError(f"FILE: {args.file} does not exist" + (" or is not a file" if path.exists() else ""))
    text, state = show_state(path)
    if state == "unreadable":
        raise UsageError(f"FILE: {text}")
    print(text)
    return 0 if state == "ok" else 1


COMMANDS = {"run": cmd_run, "fe": cmd_fe, "laws": cmd_laws, "claims": cmd_claims, "show": cmd_show}


def main(argv: list[str] | None = None) -> int:
    from .claims.load import ClaimsError  # a damaged claims file is the user's input: a message, no traceback
    from .io.yaml_files import YamlFileError
    from .pipeline.config import ConfigError

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except ConfigError as exc:
        parser.exit(2, f"stickslip {args.command}: error: {_as_option(str(exc))}\n")
    except (UsageError, FileNotFoundError, ClaimsError, YamlFileError) as exc:
        parser.exit(2, f"stickslip {args.command}: error: {exc}\n")


if __name__ == "__main__":
    sys.exit(main())
