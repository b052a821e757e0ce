"""Sweeps, convergence and stability studies, continuum increments -> results/fe/*.nc (one job)."""


from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.fe.params import FrictionTable
from stickslip.fe.quantities import INTERPRETATION
from stickslip.fe.step_halving import apply_step_halving
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.studies.fe_config import PERTURBED_FIELDS, scene_mapping
from stickslip.studies.fe_convergence import convergence_dataset
from stickslip.studies.fe_increments import increments_dataset
from stickslip.studies.fe_stability import stability_dataset
from stickslip.studies.fe_sweeps import sweep_dataset, sweep_half_step

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
cfg = snakemake.params.config  # noqa: F821  (the studies' sections and base scenes: studies.fe_config.job_config)
out = snakemake.output  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
ensemble = EnsembleSpec.from_mapping(snakemake.params.ensemble)  # noqa: F821  (claimed: sweeps, stability, increments)
for name, path in zip(snakemake.params.sweeps, out.sweeps, strict=True):  # noqa: F821
    ds = ensemble_dataset(
        lambda c, name=name: sweep_dataset(c, name, friction),
        cfg,
        ensemble,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    ds = apply_step_halving(ds, sweep_half_step(cfg, name, friction), along=cfg["sweeps"][name]["coord"])
    method = {"integrator": "central_difference", "sweep": name}
    write_dataset(ds, path, scene=dict(cfg["sweeps"][name]), interpretation=INTERPRETATION, method=method)
    print(
        f"sweep {name} written; not converged at half step: {ds.attrs['step_halving_not_converged']}",
        flush=True,
    )
for kind, build in (("convergence", convergence_dataset), ("stability", stability_dataset)):
    spec = ensemble if kind == "stability" else None  # the convergence study is a spread measurement itself
    ds = ensemble_dataset(
        lambda c, build=build: build(c, friction), cfg, spec, run_id=out[kind], fields=PERTURBED_FIELDS
    )
    write_dataset(ds, out[kind], scene=dict(cfg[kind]), interpretation=INTERPRETATION, method={"study": kind})
    print(f"{kind} written", flush=True)
inc = cfg["increments"]
ds = ensemble_dataset(
    lambda c: increments_dataset(
        scene_mapping(c, inc["base"]), [tuple(m) for m in inc["meshes"]], inc["safety_factors"], inc["betas"]
    ),
    cfg,
    ensemble,
    run_id=out.increments,
    fields=PERTURBED_FIELDS,
)
write_dataset(ds, out.increments, scene=dict(inc), interpretation=INTERPRETATION, method={"kind": "eigen"})
