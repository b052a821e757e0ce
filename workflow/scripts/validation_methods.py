"""Thin wiring: work-precision of the single-equation methods on nonlinear laws (reference: switch solver)."""

from stickslip.io.netcdf import write_dataset
from stickslip.schema import LawMethodsJob, given
from stickslip.validation.datasets import methods_dataset
from stickslip.validation.methods import methods_study
from stickslip.validation.setup import law_model, switch_solver

job = LawMethodsJob.model_validate(snakemake.params.validation)  # noqa: F821
study = job.methods_per_law
reference = switch_solver(job.solver, "validation.solver")
for law, path in zip(study.laws, snakemake.output, strict=True):  # noqa: F821
    records, ref_cycle = methods_study(law_model(job, law), study, reference)
    ds = methods_dataset(records, ref_cycle)
    ds.attrs["paper_method"] = study.paper_method
    write_dataset(
        ds,
        path,
        scene={"law": given(job.laws[law]), "base_params": given(job.base_params), "t_end": study.t_end},
        interpretation="one sign equation M x'' + C x' + K x = -N mu(|v_r|) sgn(v_r); reference: switch",
        method={"reference": reference.settings, "timing": study.timing.model_dump()},
        title=f"Methods study on the {law} law: error vs CPU against the switch-model solver",
    )
