"""CalculiX peer of the continuum strip -> results/fe/peer_calculix.{nc,csv} and its two linear decks."""

from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.io.text_files import write_csv_atomic, write_text_atomic
from stickslip.studies.fe_peer import peer_study

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
rows, ds, decks = peer_study(snakemake.params.config["fe"])  # noqa: F821
for name, path in zip(snakemake.params.decks, snakemake.output.decks, strict=True):  # noqa: F821
    write_text_atomic(path, decks[name])
write_csv_atomic(snakemake.output.table, rows)  # noqa: F821
write_dataset(
    ds,
    snakemake.output.dataset,  # noqa: F821
    scene={"beam": snakemake.params.config["fe"]["defaults"]["beam"]},  # noqa: F821
    interpretation=ds.attrs["model_interpretation"],
    method={"kind": "CalculiX peer", **(snakemake.params.config["fe"]["peer"] or {})},  # noqa: F821
)
for r in rows:
    print(f"{r['quantity']}: {r['closed_form']:.6g} / {r['continuum']:.6g} / {r['calculix']:.6g} {r['unit']}")
print(f"largest |relative difference| {float(ds['max_abs_rel_diff']):.3g}")
