"""Summaries of Snakemake ``benchmark:`` files: the cost of every rule of the pipeline."""

from __future__ import annotations

import csv
import math
from pathlib import Path

from .text_files import write_csv_atomic, write_text_atomic


def _read_benchmark(path: Path) -> list[dict]:
    with path.open(newline="") as fh:
        return list(csv.DictReader(fh, delimiter="\t"))


def as_number(value) -> float:
    """A table cell as a float; NaN when it is not a number."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def summarize_benchmarks(root: Path) -> list[dict]:
    """One row per rule (the first folder under ``root``): jobs, total/max wall time, peak RSS."""
    per_rule: dict[str, list[dict]] = {}
    for path in sorted(root.rglob("*.tsv")):
        rel = path.relative_to(root)
        rule = rel.parts[0] if len(rel.parts) > 1 else rel.stem  # a rule without wildcards: <rule>.tsv
        per_rule.setdefault(rule, []).extend(_read_benchmark(path))
    rows = []
    for rule, records in sorted(per_rule.items()):
        wall = [as_number(r.get("s")) for r in records]
        rss = [as_number(r.get("max_rss")) for r in records]
        cpu = [as_number(r.get("cpu_time")) for r in records]
        rows.append(
            {
                "rule": rule,
                "jobs": len(records),
                "wall_s_total": round(sum(w for w in wall if math.isfinite(w)), 3),
                "wall_s_max": round(max((w for w in wall if math.isfinite(w)), default=math.nan), 3),
                "cpu_s_total": round(sum(c for c in cpu if math.isfinite(c)), 3),
                "peak_rss_mb": round(max((m for m in rss if math.isfinite(m)), default=math.nan), 1),
            }
        )
    return rows


def write_summary(rows: list[dict], csv_path, md_path) -> None:
    fields = ["rule", "jobs", "wall_s_total", "wall_s_max", "cpu_s_total", "peak_rss_mb"]
    write_csv_atomic(csv_path, rows, fields=fields, lineterminator="\r\n")
    total = sum(r["wall_s_total"] for r in rows)
    lines = ["| " + " | ".join(fields) + " |", "|" + "---|" * len(fields)]
    lines += ["| " + " | ".join(str(r[f]) for f in fields) + " |" for r in rows]
    lines.append(
        f"\nSum of job wall times: {total:.1f} s (jobs run in parallel, so the elapsed time is less)."
    )
    write_text_atomic(md_path, "\n".join(lines) + "\n")


# -- per-rule CPU budgets (docs/TIMING.md) ----------------------------------------------------------------

#: The markers around the per-rule budget table in docs/TIMING.md (one row per rule: rule, budget, last
#: recorded CPU and the commit it was recorded at), read and rewritten by benchmarks/bench_pipeline.py.
BUDGET_BEGIN = "<!-- rule-budgets: begin (bench_pipeline.py reads it; --record rewrites it) -->"
BUDGET_END = "<!-- rule-budgets: end -->"
BUDGET_HEADER = "| rule | CPU budget [s] | last recorded CPU [s] | recorded at |"


def read_budgets(text: str) -> dict[str, dict]:
    """rule -> {budget, last, commit} from the budget table between the markers of ``text``."""
    if BUDGET_BEGIN not in text or BUDGET_END not in text:
        raise ValueError("no per-rule budget table (its markers are missing)")
    table = text.split(BUDGET_BEGIN, 1)[1].split(BUDGET_END, 1)[0]
    out = {}
    for line in table.strip().splitlines()[2:]:
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 4:
            raise ValueError(f"budget table row {line!r}: expected 4 cells")
        out[cells[0]] = {"budget": as_number(cells[1]), "last": as_number(cells[2]), "commit": cells[3]}
    return out


def budget_rows(rule_rows: list[dict], budgets: dict[str, dict]) -> list[dict]:
    """Each rule's CPU of this run beside its budget and its last recorded CPU; a rule without a budget,
    and a budgeted rule that did not run, are rows too (so neither goes unseen)."""
    measured = {r["rule"]: r["cpu_s_total"] for r in rule_rows}
    rows = []
    for rule in sorted(set(measured) | set(budgets)):
        cpu, b = measured.get(rule, math.nan), budgets.get(rule, {})
        budget, last = b.get("budget", math.nan), b.get("last", math.nan)
        rows.append(
            {
                "rule": rule,
                "cpu_s": cpu,
                "budget_s": budget,
                "ratio": cpu / budget if budget else math.nan,
                "last_s": last,
                "change_s": cpu - last,
                "over": bool(cpu > budget) if math.isfinite(cpu) and math.isfinite(budget) else False,
            }
        )
    return rows


def budget_table(rows: list[dict], commit: str) -> str:
    """The budget table with this run's CPU as the last recorded one (budgets kept; a new rule gets a
    budget of twice its CPU, to be reviewed)."""
    lines = [BUDGET_HEADER, "|---|---|---|---|"]
    for r in rows:
        if not math.isfinite(r["cpu_s"]):
            continue  # a rule that no longer runs leaves the table
        budget = r["budget_s"] if math.isfinite(r["budget_s"]) else round(2 * r["cpu_s"] + 1.0)
        lines.append(f"| {r['rule']} | {budget:g} | {r['cpu_s']:.1f} | {commit} |")
    return "\n".join(lines)


def with_budget_table(text: str, table: str) -> str:
    head, rest = text.split(BUDGET_BEGIN, 1)
    return head + BUDGET_BEGIN + "\n" + table + "\n" + BUDGET_END + rest.split(BUDGET_END, 1)[1]
