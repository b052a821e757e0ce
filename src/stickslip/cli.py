"""The ``stickslip`` console command: your own scenario, a figure's claims, a dataset's summary.

    stickslip run --mu-s 0.6 --damping 1.0            one 1-DOF run against the baseline and the paper
    stickslip run --law stribeck mu_k=0.3 v_s=0.5      any friction law (switch solver)
    stickslip fe --scene section9_kinematic --speed 0.5 --t-end 0.1 -o s9.nc
    stickslip claims --figure 2                        the figure's claims, verdict and reasons
    stickslip show results/onedof/fig02/consistent_caption/exact.nc

Options are checked as config keys (the typed models of ``stickslip.pipeline.config_models``): a bad value
is reported with the option and the config key it sets. ``-o`` writes the dataset the pipeline would write
(``stickslip.api``), ``--plot`` the pipeline's figure of it.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from . import catalogue as paths

#: 1-DOF parameters as options: option -> config key (``onedof.scenes.<scene>.params.<key>``).
PARAMS = {
    "mass": "M [kg]",
    "stiffness": "K [N/mm]",
    "damping": "C [N s/mm]",
    "mu_s": "static friction coefficient",
    "sigma": "friction slope [s/mm]",
    "normal_force": "N [N]",
    "x0": "initial displacement [mm]",
    "v0": "initial velocity [mm/s]",
    "belt_velocity": "V_b [mm/s]",
    "belt_deceleration": "[mm/s^2]",
    "plateau_speed": "friction plateau speed [mm/s]",
}
RUN_LENGTHS = {
    "t_end": "simulated time [s]",
    "output_dt": "sample spacing [s]",
    "transient": "discarded start [s]",
}
#: The paper's metrics ``stickslip run`` prints (dataset variables).
METRICS = ("amplitude_peak_to_peak", "amplitude_peak_to_zero", "frequency_peaks", "stick_time", "slip_time")


class UsageError(Exception):
    """A bad option: the message names it (and the config key it sets)."""


def _option(key: str) -> str:
    return "--" + key.replace("_", "-")


def _as_option(message: str) -> str:
    """A config error's message with the option that set the key in front of it."""
    for line in message.splitlines():
        key = line.split(":", 1)[0]
        last = key.rsplit(".", 1)[-1]
        if key in ("scene", "reading", "method", "model") or key.startswith("fe.scenes."):
            option = "--scene" if key.startswith("fe.") else _option(key)
            return (
                f"{option}: {line.split(':', 1)[1].strip()}"
                if not key.startswith("fe.")
                else f"--scene: {line}"
            )
        if ".law" in key and "'switch' solver only" in line:
            return f"--law/--method ({key}): {line.split(':', 1)[1].strip()}"
        if ".law" in key:
            return f"--law ({key}): {line.split(':', 1)[1].strip()}"
        if last in PARAMS or last in RUN_LENGTHS:
            return f"{_option(last)} ({key}): {line.split(':', 1)[1].strip()}"
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


def _common(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--configfile",
        action="append",
        default=[],
        metavar="FILE",
        help="config overlay over config/*.yaml (as snakemake --configfile); repeatable",
    )
    parser.add_argument("--root", type=Path, help="project folder (default: the checkout, or the cwd)")
    parser.add_argument(
        "-o", "--output", type=Path, help="write the dataset (netCDF) the pipeline would write"
    )
    parser.add_argument("--plot", type=Path, help="draw the pipeline's figure of the run to this PNG")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stickslip", description=__doc__.split("\n\n")[0], formatter_class=argparse.RawTextHelpFormatter
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    run = sub.add_parser(
        "run",
        help="one 1-DOF run: the paper's metrics against the baseline and the paper",
        description="One 1-DOF run (mass on a moving belt): amplitude, frequency, stick and slip time next "
        "to the baseline's and the paper's reported values. Parameters not given are the scene's.",
    )
    run.add_argument("--scene", help="base scene (onedof.scenes; default: the baseline's)")
    run.add_argument("--reading", help="reading of the paper's friction (onedof.readings)")
    run.add_argument("--method", help="integration method (onedof.methods; default exact, switch with --law)")
    for key, text in PARAMS.items():
        run.add_argument(_option(key), dest=key, type=float, metavar="X", help=text)
    run.add_argument("--units", choices=["as_given", "si"], help="how the parameters' units are read")
    for key, text in RUN_LENGTHS.items():
        run.add_argument(_option(key), dest=key, type=float, metavar="S", help=text)
    run.add_argument(
        "--law",
        nargs="+",
        metavar=("KIND", "KEY=VALUE"),
        help="friction law replacing the reading's: affine, coulomb, stribeck, rational, tabulated, then "
        "its parameters (mu_s defaults to the run's), e.g. --law stribeck mu_k=0.3 v_s=0.5",
    )
    run.add_argument("--ensemble", action="store_true", help="add the config's perturbation ensemble")
    _common(run)

    fe = sub.add_parser(
        "fe",
        help="one beam-on-disc scene, with progress lines",
        description="One beam-on-disc scene as rule fe_reading computes it (perturbation ensemble and "
        "step-halving check included unless --no-ensemble).",
    )
    fe.add_argument("--scene", required=True, help="fe.scenes name, or its stem with --speed")
    fe.add_argument("--speed", type=float, help="disc surface speed [mm/s] picking the scene (0.5: _0p5mm_s)")
    fe.add_argument("--reading", help="FE reading (fe.readings; default: the first)")
    fe.add_argument("--model", choices=["beam", "continuum"], default="beam", help="FE model (default beam)")
    fe.add_argument("--t-end", dest="t_end", type=float, metavar="S", help="simulated window [s]")
    fe.add_argument("--no-ensemble", dest="ensemble", action="store_false", help="the base run only")
    _common(fe)

    claims = sub.add_parser(
        "claims",
        help="a paper figure's claims, verdict and reasons (after a build)",
        description=f"Reads {paths.claims_table()} (rule claims_table) and the claims files.",
    )
    claims.add_argument("--figure", type=int, required=True, help="paper figure number")
    claims.add_argument("--reading", help="show this reading (default: the figure's best)")
    claims.add_argument("--root", type=Path, help="project folder")

    show = sub.add_parser("show", help="readable summary of a result dataset")
    show.add_argument("file", type=Path, help="a netCDF dataset the pipeline or this command wrote")
    return parser


# -- run -------------------------------------------------------------------------------------------------


def _fmt(value, unit: str = "") -> str:
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if value != value:
        return "n/a"
    return f"{value:.4g}" + (f" {unit}" if unit else "")


def _metrics(ds) -> dict:
    return {m: float(ds[m]) for m in METRICS if m in ds and ds[m].ndim == 0}


def baseline_metrics(config: dict, reading: str, root: Path) -> tuple[dict, str]:
    """The baseline's metrics in ``reading``: from the build when its dataset exists, else computed."""
    from .catalogue import onedof_dataset
    from .io.netcdf import read_dataset

    base = config["onedof"]["baseline"]
    path = root / onedof_dataset(base["scene"], reading, base["method"])
    if path.is_file():
        return _metrics(read_dataset(path)), str(path.relative_to(root))
    from .studies.onedof import scene_run_dataset
    from .studies.specs import run_spec

    return _metrics(scene_run_dataset(run_spec(config, base["scene"], reading, base["method"]))), "computed"


def paper_values(config: dict, root: Path, scene: str | None = None) -> dict[str, list[tuple[float, str]]]:
    """The paper's numbers for a scene (default: the baseline's): every ``value`` claim on its dataset, so
    ``--scene fig06`` is compared with Fig. 6's numbers, not Fig. 2's."""
    from .catalogue import onedof_dataset
    from .claims.load import load_claims

    base = config["onedof"]["baseline"]
    target = onedof_dataset(scene or base["scene"], "{reading}", base["method"])
    # read (and check) only the files with a claim on the baseline's dataset: the run waits for no others
    files = [p for p in sorted((root / "config" / "claims").glob("*.yaml")) if target in p.read_text()]
    out: dict[str, list[tuple[float, str]]] = {}
    for row in load_claims(files):
        if row.kind == "value" and row.dataset == target and row.variable in METRICS:
            out.setdefault(row.variable, []).append((row.value, row.id))
    return out


def cmd_run(args) -> int:
    from . import api
    from .pipeline.config import ConfigError

    started = time.perf_counter()
    params = {k: getattr(args, k) for k in PARAMS if getattr(args, k) is not None}
    if args.units is not None:
        params["units"] = args.units
    run = {k: getattr(args, k) for k in RUN_LENGTHS if getattr(args, k) is not None}
    law = _law(args.law)
    try:
        root = api.project_root(args.root)
        config = api.load_project_config(args.configfile, root)
        ds = api.simulate(
            args.scene,
            reading=args.reading,
            method=args.method,
            law=law,
            ensemble=args.ensemble,
            output=args.output,
            root=root,
            config=config,
            **run,
            **params,
        )
        reading = args.reading or config["onedof"]["baseline"]["reading"]
        base, where = baseline_metrics(config, reading, root)
    except ConfigError as exc:
        raise UsageError(_as_option(str(exc))) from None
    from .analysis.metrics import metric_attrs

    paper = paper_values(config, root, args.scene)
    print(f"outcome: {ds.attrs.get('status', '?')} - {ds.attrs.get('message', '')}")
    print(f"{ds.attrs.get('title', '').strip()}")
    print(f"  {ds.attrs.get('scene_description', '')}; solver: {ds.attrs.get('solver_message', '')}")
    rows = [("metric", "this run", f"baseline ({where})", "paper (claim)")]
    for m in METRICS:
        unit = metric_attrs(m)["units"]
        mine = _metrics(ds).get(m)
        reported = "; ".join(f"{_fmt(v, unit)} ({cid})" for v, cid in paper.get(m, [])) or "-"
        rows.append((m, _fmt(mine, unit), _fmt(base.get(m), unit), reported))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for row in rows:
        print("  " + "  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())
    if int(ds.solver_status) != 0 or not _metrics(ds):
        print(f"  no limit-cycle metrics (n/a): the run's outcome is {ds.attrs.get('message', 'unknown')}")
    if args.output:
        print(f"wrote {args.output}")
    if args.plot:
        _plot_onedof(ds, config, args, reading)
    print(f"({time.perf_counter() - started:.1f} s)")
    return 0 if ds.attrs.get("status") != "failed" else 1  # a divergence is an answer; a failure is not


def _plot_onedof(ds, config: dict, args, reading: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .presentation.plots import onedof_figure

    scene = ds.attrs.get("scene_name", "")
    kind = next(
        (f.get("plot", "timeseries") for f in config["onedof"]["figures"].values() if f["scene"] == scene),
        "timeseries",
    )
    method = ds.attrs.get("method_name", "")
    spec = {"title": ds.attrs.get("title", ""), "scene": scene, "plot": kind, "readings": [reading]}
    fig = onedof_figure({method: ds}, {**spec, "methods": [method]}, reading=reading)
    fig.savefig(args.plot, dpi=110)
    plt.close(fig)
    print(f"wrote {args.plot}")


# -- fe --------------------------------------------------------------------------------------------------


def cmd_fe(args) -> int:
    from . import api
    from .io.progress import step_callback
    from .pipeline.config import ConfigError

    started = time.perf_counter()

    def progress(label):
        return step_callback(label, every=2.0, sink=lambda line: print(line, file=sys.stderr, flush=True))

    print(f"running {args.scene} ({args.model}); progress every 2 s on stderr", file=sys.stderr, flush=True)
    try:
        ds = api.simulate_fe(
            args.scene,
            speed=args.speed,
            reading=args.reading,
            model=args.model,
            t_end=args.t_end,
            ensemble=args.ensemble,
            progress=progress,
            output=args.output,
            configfiles=args.configfile,
            root=args.root,
        )
    except ConfigError as exc:
        raise UsageError(_as_option(str(exc))) from None
    summary(ds)
    if args.output:
        print(f"wrote {args.output}")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        from .presentation.fe_plots import fe_scene_figure

        fe_scene_figure(ds, None, title=ds.attrs.get("title", "")).savefig(args.plot, dpi=100)
        print(f"wrote {args.plot}")
    print(f"({time.perf_counter() - started:.1f} s)")
    return 0


# -- claims ----------------------------------------------------------------------------------------------


def cmd_claims(args) -> int:
    from . import api
    from .claims.load import load_claims
    from .claims.table import read_table
    from .presentation.verdicts import VERDICT_RULE, is_evidence, rows_in_reading, tally

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
    # the primary reading (declared in docs/READINGS.md) unless the user asks for another
    reading = args.reading or (config["claims"]["primary_reading"] if any(r["reading"] for r in rows) else "")
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
            f"- {r['claim']}: {r['status']}{apart}  reported {r['reported']} {r['unit']}, "
            f"measured {r['measured']}"
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


def summary(ds, checksum: str = "") -> None:
    """Print the dataset's summary (the text the replication page previews it with)."""
    from .presentation.show import summary_text

    print(summary_text(ds, checksum))


def cmd_show(args) -> int:
    from .presentation.show import show_text

    if not args.file.is_file():
        raise UsageError(f"FILE: {args.file} does not exist")
    print(show_text(args.file))
    return 0


COMMANDS = {"run": cmd_run, "fe": cmd_fe, "claims": cmd_claims, "show": cmd_show}


def main(argv: list[str] | None = None) -> int:
    from .claims.load import ClaimsError  # a damaged claims file is the user's input: a message, no traceback

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except (UsageError, FileNotFoundError, ClaimsError) as exc:
        parser.exit(2, f"stickslip {args.command}: error: {exc}\n")


if __name__ == "__main__":
    sys.exit(main())
