"""CalculiX peer of the continuum strip -> results/fe/peer_calculix.{nc,csv} and its two linear decks."""

from stickslip.fe.params import BeamParams
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.io.text_files import write_csv_atomic, write_text_atomic
from stickslip.schema.fe import FePeer
from stickslip.studies.fe_peer import peer_study

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
par = snakemake.params  # noqa: F821  (the strip fe.defaults.beam and fe.peer)
beam, peer = BeamParams.from_mapping(par.beam), FePeer.model_validate(par.peer)
rows, ds, decks = peer_study(beam, peer)
for name, path in zip(par.decks, snakemake.output.decks, strict=True):  # noqa: F821
    write_text_atomic(path, decks[name])
write_csv_atomic(snakemake.output.table, rows)  # noqa: F821
write_dataset(
    ds,
    snakemake.output.dataset,  # noqa: F821
    scene={"beam": par.beam},
    interpretation=ds.attrs["model_interpretation"],
    method={"kind": "CalculiX peer", **par.peer},
)
for r in rows:
    print(f"{r['quantity']}: {r['closed_form']:.6g} / {r['continuum']:.6g} / {r['calculix']:.6g} {r['unit']}")
print(f"largest |relative difference| {float(ds['max_abs_rel_diff']):.3g}")
