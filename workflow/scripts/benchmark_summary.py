"""Thin wiring: tabulate wall time and peak memory of every job's benchmark file, per rule."""

from pathlib import Path

from stickslip.io.benchmarks import summarize_benchmarks, write_summary

rows = summarize_benchmarks(Path(snakemake.params.root))
write_summary(rows, snakemake.output.csv, snakemake.output.md)
