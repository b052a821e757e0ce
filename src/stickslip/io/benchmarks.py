"""Summaries of Snakemake ``benchmark:`` files: the cost of every rule of the pipeline."""

from __future__ import annotations

import csv
import math
from pathlib import Path


def _read_benchmark(path: Path) -> list[dict]:
    with path.open(newline="") as fh:
        return list(csv.DictReader(fh, delimiter="\t"))


def _num(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def summarize_benchmarks(root: Path) -> list[dict]:
    """One row per rule (the first folder under ``root``): jobs, total/max wall time, peak RSS."""
    per_rule: dict[str, list[dict]] = {}
    for path in sorted(root.rglob("*.tsv")):
        rule = path.relative_to(root).parts[0]
        per_rule.setdefault(rule, []).extend(_read_benchmark(path))
    rows = []
    for rule, records in sorted(per_rule.items()):
        wall = [_num(r.get("s")) for r in records]
        rss = [_num(r.get("max_rss")) for r in records]
        cpu = [_num(r.get("cpu_time")) for r in records]
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
    csv_path, md_path = Path(csv_path), Path(md_path)
    csv_path.parent.mkdir(parents=True, exist_ok=True)
    with csv_path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    total = sum(r["wall_s_total"] for r in rows)
    lines = ["| " + " | ".join(fields) + " |", "|" + "---|" * len(fields)]
    lines += ["| " + " | ".join(str(r[f]) for f in fields) + " |" for r in rows]
    lines.append(
        f"\nSum of job wall times: {total:.1f} s (jobs run in parallel, so the elapsed time is less)."
    )
    md_path.write_text("\n".join(lines) + "\n")
