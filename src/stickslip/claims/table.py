"""The deviations table: written (CSV for machines, Markdown for people), read back, and checked against
the pinned statuses (``python -m stickslip.claims.table check results/claims/deviations.csv``)."""

from __future__ import annotations

import csv
import sys
from dataclasses import asdict
from pathlib import Path

from ..io.text_files import write_csv_atomic, write_text_atomic
from .evaluate import ClaimResult
from .verdicts import status_counts

FIELDS = [f for f in ClaimResult.__dataclass_fields__]


def _cell(value) -> str:
    """A number to 4 significant digits, words as they are."""
    return f"{value:.4g}" if isinstance(value, float | int) else str(value)


def write_table(results: list[ClaimResult], csv_path, md_path=None) -> None:
    """CSV (machine) and Markdown (human) deviations tables, each written atomically."""
    write_csv_atomic(csv_path, [asdict(r) for r in results], fields=FIELDS, lineterminator="\r\n")
    if md_path:
        lines = [
            "| claim | reading | figure | quantity | reported | measured | unit | margin | spread | status "
            "| expected | reason |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in results:
            flag = "" if r.matches_expected else " **(changed)**"
            lines.append(
                f"| {r.claim} | {r.reading or '-'} | {r.figure} | {r.quantity} | {_cell(r.reported)} | "
                f"{r.measured:.4g} | {r.unit} | {r.margin:.3g} | {r.spread:.3g} | {r.status}{flag} | "
                f"{r.expected} | {r.reason} |"
            )
        write_text_atomic(md_path, "\n".join(lines) + "\n")


def read_table(csv_path) -> list[dict]:
    with Path(csv_path).open(newline="") as fh:
        return list(csv.DictReader(fh))


def unexpected(rows: list[dict]) -> list[dict]:
    return [r for r in rows if str(r["matches_expected"]) != "True"]


#: Causes that leave a row unmeasured by its own data (stickslip.claims.evaluate.NOT_COMPARABLE_CAUSES).
UNMEASURED = ("failure", "withheld", "nothing")


def constructions_not_shown(rows: list[dict]) -> list[dict]:
    """``by_construction`` rows whose own data do not show the construction: undecided within the run's
    noise (including a value that moves between dt and dt/2), or left unmeasured. A row says its outcome is
    fixed by the stated setup; the build checks that the run, at both step sizes, says so too."""
    return [
        r
        for r in rows
        if r.get("evidence") == "by_construction"
        and (r["status"] == "indistinguishable" or r.get("cause", "") in UNMEASURED)
    ]


def pin_line(statuses: dict[str, str]) -> str:
    """The ``expected:`` value of one claim from its measured status per reading: one status, or a default
    with the readings that differ. The default is the main table's status of a row without readings (key
    ''; its other keys are the FE readings), else the most frequent status."""
    statuses = dict(statuses)
    values = list(statuses.values())
    if "" in statuses:
        default = statuses.pop("")
    else:
        default = max(sorted(set(values)), key=values.count)  # ties: alphabetical, so the file is stable
    others = {r: s for r, s in statuses.items() if s != default}
    if not others:
        return default
    return "{" + ", ".join([f"default: {default}"] + [f"{r}: {s}" for r, s in others.items()]) + "}"


def pin_statuses(tables: list[list[dict]], claims_files: list[Path]) -> list[str]:
    """Rewrite the ``expected:`` of each claim whose status in the first (checked) table differs from its
    pin, to its measured statuses in every table (the main claims table, then e.g. the FE readings table):
    the reviewed edit a deliberate change in what is reproduced needs. Returns the ids pinned anew."""
    measured: dict[str, dict[str, str]] = {r["claim"]: {} for r in unexpected(tables[0])}
    for rows in tables:
        for r in rows:
            if r["claim"] in measured:
                measured[r["claim"]][r["reading"]] = r["status"]
    for path in claims_files:
        lines, out, current, skip = path.read_text().splitlines(keepends=True), [], None, False
        for line in lines:
            if line.startswith("- id: "):
                current = line.split(":", 1)[1].strip()
            if skip and line.startswith("    "):  # the old pin's block mapping
                continue
            skip = False
            if current in measured and line.startswith("  expected:"):
                out.append(f"  expected: {pin_line(measured[current])}\n")
                skip = line.rstrip() == "  expected:"
                continue
            out.append(line)
        path.write_text("".join(out))
    return sorted(measured)


def main(argv=None) -> int:
    """``python -m stickslip.claims.table check TABLE.csv``: exit 1 if any status differs from its pin.
    ``... pin TABLE.csv [FE_READINGS.csv] config/claims/*.yaml``: pin the measured statuses of the claims
    whose status in TABLE changed, in every table given (then review the diff)."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) >= 3 and argv[0] == "pin":
        tables = [read_table(p) for p in argv[1:] if p.endswith(".csv")]
        changed = pin_statuses(tables, [Path(p) for p in argv[1:] if not p.endswith(".csv")])
        print(f"{len(changed)} claims pinned anew: " + ", ".join(changed))
        return 0
    if len(argv) != 2 or argv[0] != "check":
        print(
            "usage: python -m stickslip.claims.table check results/claims/deviations.csv\n"
            "       python -m stickslip.claims.table pin results/claims/deviations.csv "
            "results/fe/readings_claims.csv config/claims/*.yaml",
            file=sys.stderr,
        )
        return 2
    rows = read_table(argv[1])
    bad = unexpected(rows)
    for r in bad:
        print(
            f"CHANGED {r['claim']} [{r['reading'] or '-'}]: measured status {r['status']}, "
            f"pinned {r['expected']} ({r['reason']})"
        )
    unshown = constructions_not_shown(rows)
    for r in unshown:
        print(
            f"NOT SHOWN {r['claim']} [{r['reading'] or '-'}]: by construction, but its data leave it "
            f"{r['status']} ({r['reason']})"
        )
    bad = bad + unshown
    counts = status_counts(r["status"] for r in rows)
    print(
        f"{len(rows)} claim checks: "
        + ", ".join(f"{v} {k}" for k, v in counts.items())
        + f"; {len(bad) - len(unshown)} differ from the pinned status"
        + f"; {len(unshown)} by construction not shown"
    )
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
