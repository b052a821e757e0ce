"""Peer-comparison and round-trip results as CSV tables and CF netCDF datasets (written by thin scripts)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable, table_variables
from ..io.text_files import write_csv_atomic
from .compare import TOLERANCE_CLASS, RoundTrip
from .cycle import QUANTITIES


def write_csv(rows: list[dict], path: str | os.PathLike) -> Path:
    """Rows (dicts with the same keys) to CSV, atomically, floats to 12 significant digits (lines end in
    CRLF, the csv module's default)."""
    rows = [{k: (f"{v:.12g}" if isinstance(v, float) else v) for k, v in row.items()} for row in rows]
    return write_csv_atomic(path, rows, lineterminator="\r\n")


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
            data[f"{q}_{ref}"] = cf_variable("law", got[ref], units, f"{long_name} ({label})")
        data[f"{q}_cvode_within"] = cf_variable(
            "law",
            within,
            "1",
            f"{q}: switch vs CVODE within tolerance",
            flag_values=np.array([-1, 0, 1], dtype=np.int8),
            flag_meanings="not_compared exceeds within",
        )
        tol = tolerances[TOLERANCE_CLASS[q]]
        data[f"{q}_tolerance"] = cf_variable((), tol.abs, units, f"tolerance on {q}", reason=tol.reason)
    rhs = [float(runs[n]["cvode_counters"]["rhs_evaluations"]) for n in laws]
    data["cvode_rhs_evaluations"] = cf_variable("law", rhs, "1", "CVODE right-hand-side evaluations")
    phases = [float(runs[n]["segments"]) for n in laws]
    data["switch_phases"] = cf_variable("law", phases, "1", "stick and slip phases of the switch-model run")
    # names as an auxiliary coordinate: a CF coordinate variable must be numeric and monotonic
    names = ("law", laws, {"long_name": "friction law (config validation.laws)"})
    return xr.Dataset(data, coords={"law_name": names})


#: The differences of a round trip's two runs: name -> (units, long name).
DIFFERENCES = {
    "max_abs_dx": ("mm", "largest displacement difference over the run"),
    "max_abs_dv": ("mm s-1", "largest velocity difference over the run"),
    "table_error_inside": ("1", "max |mu_table - mu_law| up to the table's last row"),
    "table_error_beyond": ("1", "max |mu_table - mu_law| beyond the last row (table held constant)"),
}


def round_trip_rows(cases: dict[str, RoundTrip]) -> list[dict]:
    """Per case: each cycle quantity of the source and the table run and their difference, then the
    differences of the two runs (no cycle values: NaN)."""
    return [
        dict(case=case, quantity=q, units=units, source_cycle=source, table_cycle=table, difference=diff)
        for case, rt in cases.items()
        for q, units, source, table, diff in (
            *(
                (q, u, float(rt.source[q]), float(rt.table[q]), float(rt.table[q] - rt.source[q]))
                for q, (u, _) in QUANTITIES.items()
            ),
            *((key, u, np.nan, np.nan, float(rt.differences[key])) for key, (u, _) in DIFFERENCES.items()),
        )
    ]


def round_trip_dataset(main: RoundTrip, cases: dict[str, RoundTrip], source_check: float) -> xr.Dataset:
    """The Fig. 17 round trip as time series and friction curves, plus every case's cycle quantities."""
    names = list(cases)
    time = cf_variable("time", main.t, "s", "time", standard_name="time", axis="T")
    data = {
        "x_source": cf_variable("time", main.x_source, "mm", "displacement, source law"),
        "v_source": cf_variable("time", main.v_source, "mm s-1", "velocity, source law"),
        "x_table": cf_variable("time", main.x_table, "mm", "displacement, driven by the table"),
        "v_table": cf_variable("time", main.v_table, "mm s-1", "velocity, driven by the table"),
        "mu_law": cf_variable("speed", main.mu_law, "1", "source law mu(|v_r|)"),
        "mu_table": cf_variable("speed", main.mu_table, "1", "table mu(|v_r|): PCHIP, held beyond"),
        "source_check": cf_variable(
            (), source_check, "mm", "max |x(re-run source) - x(dataset the table came from)|"
        ),
    }
    for q, (units, long_name) in QUANTITIES.items():
        for side in ("source", "table"):
            values = [getattr(cases[c], side)[q] for c in names]
            data[f"{q}_{side}"] = cf_variable("case", values, units, f"{long_name}, {side} law")
    data |= table_variables("case", DIFFERENCES, lambda key: [cases[c].differences[key] for c in names])
    speeds = {
        "last_row_speed": ("mm s-1", "relative speed of the table's last row"),
        "max_cycle_speed": ("mm s-1", "largest sampled |v_r| of the source run"),
    }
    data |= table_variables("case", speeds, lambda name: [getattr(cases[c], name) for c in names])
    coords = {
        "time": time,
        "speed": cf_variable("speed", main.speed_grid, "mm s-1", "relative speed |v_r|"),
        "case_name": ("case", names, {"long_name": "round-trip case"}),  # auxiliary, as law_name
    }
    return xr.Dataset(data, coords=coords)


def methods_dataset(records: list[dict], ref_cycle: dict) -> xr.Dataset:
    """Work-precision of the methods on one law: dimension ``method`` (labels as an auxiliary coordinate)."""
    measured = {
        "state": ("1", "max-norm state error relative to the reference's peak-to-peak x and v"),
        "period_error": ("1", "relative error of the limit-cycle period"),
        "amplitude_error": ("1", "relative error of the peak-to-peak amplitude"),
        "cpu_time": ("s", "process CPU time of one run (minimum over repeats)"),
        "rhs_evaluations": ("1", "right-hand-side evaluations"),
    }
    data = table_variables("method", measured, lambda name: [float(r[name]) for r in records])
    data["failed"] = cf_variable(
        "method",
        np.array([r["status"] != "ok" for r in records], dtype=np.int8),
        "1",
        "run failed",
        flag_values=np.array([0, 1], dtype=np.int8),
        flag_meanings="ok failed",
    )
    data["reference_period"] = cf_variable((), float(ref_cycle["period"]), "s", "reference period")
    amplitude = float(ref_cycle["amplitude"])
    data["reference_amplitude"] = cf_variable((), amplitude, "mm", "reference peak-to-peak amplitude")
    coords = {
        "method_label": ("method", [r["label"] for r in records], {"long_name": "method and settings"}),
        "solver": ("method", [r["solver"] for r in records], {"long_name": "method family"}),
    }
    return xr.Dataset(data, coords=coords)
