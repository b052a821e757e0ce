"""Peer-comparison and round-trip results as CSV tables and CF netCDF datasets (written by thin scripts)."""

from __future__ import annotations

import csv
import os
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

from ..io.netcdf import publish
from .compare import RoundTrip
from .cycle import QUANTITIES


def write_csv(rows: list[dict], path: str | os.PathLike) -> Path:
    """Rows (dicts with the same keys) to CSV, atomically: a hidden temporary file, then rename."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
            writer.writeheader()
            for row in rows:
                writer.writerow({k: (f"{v:.12g}" if isinstance(v, float) else v) for k, v in row.items()})
        publish(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def peer_dataset(rows: list[dict], runs: dict[str, dict], tolerances: dict) -> xr.Dataset:
    """Per quantity q (each with its own units), over the ``law`` dimension: q_switch, q_cvode,
    q_closed_form (NaN where there is none) and q_cvode_within (1 within tolerance, 0 exceeds)."""
    laws = list(dict.fromkeys(r["law"] for r in rows))
    data = {}
    for q, (units, long_name) in QUANTITIES.items():
        got = {ref: np.full(len(laws), np.nan) for ref in ("switch", "cvode", "closed_form")}
        within = np.full(len(laws), -1, dtype=np.int8)
        for r in rows:
            if r["quantity"] != q:
                continue
            i = laws.index(r["law"])
            got["switch"][i] = r["switch"]
            got[r["reference"]][i] = r["reference_value"]
            if r["reference"] == "cvode":
                within[i] = 1 if r["status"] == "within" else 0
        for ref, label in (
            ("switch", "switch-model solver"),
            ("cvode", "SUNDIALS CVODE hybrid model"),
            ("closed_form", "textbook closed form"),
        ):
            data[f"{q}_{ref}"] = ("law", got[ref], {"units": units, "long_name": f"{long_name} ({label})"})
        data[f"{q}_cvode_within"] = (
            "law",
            within,
            {
                "units": "1",
                "long_name": f"{q}: switch vs CVODE within tolerance",
                "flag_values": np.array([-1, 0, 1], dtype=np.int8),
                "flag_meanings": "not_compared exceeds within",
            },
        )
        tol = tolerances[_tol_class(q)]
        data[f"{q}_tolerance"] = (
            (),
            tol.abs,
            {"units": units, "long_name": f"tolerance on {q}", "reason": tol.reason},
        )
    data["cvode_rhs_evaluations"] = (
        "law",
        [float(runs[n]["cvode_counters"]["rhs_evaluations"]) for n in laws],
        {"units": "1", "long_name": "CVODE right-hand-side evaluations"},
    )
    data["switch_phases"] = (
        "law",
        [float(runs[n]["segments"]) for n in laws],
        {"units": "1", "long_name": "stick and slip phases of the switch-model run"},
    )
    # names as an auxiliary coordinate: a CF coordinate variable must be numeric and monotonic
    names = ("law", laws, {"long_name": "friction law (config validation.laws)"})
    return xr.Dataset(data, coords={"law_name": names})


def _tol_class(quantity: str) -> str:
    return "time" if QUANTITIES[quantity][0] == "s" else "position"


def round_trip_rows(cases: dict[str, RoundTrip]) -> list[dict]:
    rows = []
    for case, rt in cases.items():
        for q, (units, _) in QUANTITIES.items():
            rows.append(
                {
                    "case": case,
                    "quantity": q,
                    "units": units,
                    "source_cycle": float(rt.source[q]),
                    "table_cycle": float(rt.table[q]),
                    "difference": float(rt.table[q] - rt.source[q]),
                }
            )
        d = rt.differences
        for key, units in (
            ("max_abs_dx", "mm"),
            ("max_abs_dv", "mm s-1"),
            ("table_error_inside", "1"),
            ("table_error_beyond", "1"),
        ):
            rows.append(
                {
                    "case": case,
                    "quantity": key,
                    "units": units,
                    "source_cycle": np.nan,
                    "table_cycle": np.nan,
                    "difference": float(d[key]),
                }
            )
    return rows


def round_trip_dataset(main: RoundTrip, cases: dict[str, RoundTrip], source_check: float) -> xr.Dataset:
    """The Fig. 17 round trip as time series and friction curves, plus every case's cycle quantities."""
    names = list(cases)
    time = ("time", main.t, {"units": "s", "long_name": "time", "standard_name": "time", "axis": "T"})
    data = {
        "x_source": ("time", main.x_source, {"units": "mm", "long_name": "displacement, source law"}),
        "v_source": ("time", main.v_source, {"units": "mm s-1", "long_name": "velocity, source law"}),
        "x_table": ("time", main.x_table, {"units": "mm", "long_name": "displacement, driven by the table"}),
        "v_table": ("time", main.v_table, {"units": "mm s-1", "long_name": "velocity, driven by the table"}),
        "mu_law": ("speed", main.mu_law, {"units": "1", "long_name": "source law mu(|v_r|)"}),
        "mu_table": (
            "speed",
            main.mu_table,
            {"units": "1", "long_name": "table mu(|v_r|): PCHIP, held beyond"},
        ),
        "source_check": (
            (),
            source_check,
            {"units": "mm", "long_name": "max |x(re-run source) - x(dataset the table came from)|"},
        ),
    }
    for q, (units, long_name) in QUANTITIES.items():
        for side in ("source", "table"):
            values = [getattr(cases[c], side)[q] for c in names]
            data[f"{q}_{side}"] = ("case", values, {"units": units, "long_name": f"{long_name}, {side} law"})
    for key, units, long_name in (
        ("max_abs_dx", "mm", "largest displacement difference over the run"),
        ("max_abs_dv", "mm s-1", "largest velocity difference over the run"),
        ("table_error_inside", "1", "max |mu_table - mu_law| up to the table's last row"),
        ("table_error_beyond", "1", "max |mu_table - mu_law| beyond the last row (table held constant)"),
    ):
        data[key] = (
            "case",
            [cases[c].differences[key] for c in names],
            {"units": units, "long_name": long_name},
        )
    data["last_row_speed"] = (
        "case",
        [cases[c].last_row_speed for c in names],
        {"units": "mm s-1", "long_name": "relative speed of the table's last row"},
    )
    data["max_cycle_speed"] = (
        "case",
        [cases[c].max_cycle_speed for c in names],
        {"units": "mm s-1", "long_name": "largest sampled |v_r| of the source run"},
    )
    coords = {
        "time": time,
        "speed": ("speed", main.speed_grid, {"units": "mm s-1", "long_name": "relative speed |v_r|"}),
        "case_name": ("case", names, {"long_name": "round-trip case"}),  # auxiliary, as law_name
    }
    return xr.Dataset(data, coords=coords)


def methods_dataset(records: list[dict], ref_cycle: dict) -> xr.Dataset:
    """Work-precision of the methods on one law: dimension ``method`` (labels as an auxiliary coordinate)."""
    fields = (
        ("state", "1", "max-norm state error relative to the reference's peak-to-peak x and v"),
        ("period_error", "1", "relative error of the limit-cycle period"),
        ("amplitude_error", "1", "relative error of the peak-to-peak amplitude"),
        ("cpu_time", "s", "process CPU time of one run (minimum over repeats)"),
        ("rhs_evaluations", "1", "right-hand-side evaluations"),
    )
    data = {
        name: ("method", [float(r[name]) for r in records], {"units": units, "long_name": long_name})
        for name, units, long_name in fields
    }
    data["failed"] = (
        "method",
        np.array([r["status"] != "ok" for r in records], dtype=np.int8),
        {
            "units": "1",
            "long_name": "run failed",
            "flag_values": np.array([0, 1], dtype=np.int8),
            "flag_meanings": "ok failed",
        },
    )
    data["reference_period"] = (
        (),
        float(ref_cycle["period"]),
        {"units": "s", "long_name": "reference period"},
    )
    data["reference_amplitude"] = (
        (),
        float(ref_cycle["amplitude"]),
        {"units": "mm", "long_name": "reference peak-to-peak amplitude"},
    )
    coords = {
        "method_label": ("method", [r["label"] for r in records], {"long_name": "method and settings"}),
        "solver": ("method", [r["solver"] for r in records], {"long_name": "method family"}),
    }
    return xr.Dataset(data, coords=coords)
