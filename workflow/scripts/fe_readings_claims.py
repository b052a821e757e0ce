"""Every FE claim under every FE reading -> results/fe/readings_claims.csv (the claims table checks the
default reading; here each row reads the same runs in each reading, looked up in the catalogue)."""

import csv
from dataclasses import asdict
from functools import lru_cache

from stickslip.catalogue import fe_scene_entries
from stickslip.claims.models import annotate, read_comparison
from stickslip.claims.per_reading import claims_per_reading
from stickslip.io.netcdf import read_dataset
from stickslip.io.progress import log_to_file

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
# the model comparison (default reading) decides which model may decide a row, in every reading alike
comparison = read_comparison(snakemake.input.comparison)  # noqa: F821
claims = annotate(snakemake.params.claims, comparison, snakemake.params.cross_scene)  # noqa: F821
# every FE scene under every reading: where a row's run is found again in another reading
entries = {e.path: e for e in fe_scene_entries(snakemake.params.scenes, snakemake.params.readings)}  # noqa: F821
results = claims_per_reading(
    claims,
    snakemake.params.readings,  # noqa: F821
    entries,
    lru_cache(maxsize=None)(read_dataset),
)
rows = [asdict(r) for r in results]
with open(snakemake.output[0], "w", newline="") as f:  # noqa: F821
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
