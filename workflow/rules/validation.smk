# Issue 13: the switch-model solver for any friction law, checked against an independent program
# (SUNDIALS CVODE), the textbook Coulomb cycle, and the Fig. 17 round trip.
from stickslip.validation.setup import ValidationSetup

VALIDATION = ValidationSetup(config["validation"])
VALIDATION_LAWS = VALIDATION.law_names()

ALL_TARGETS.extend(
    expand("results/validation/peer_{law}.csv", law=VALIDATION_LAWS)
    + expand(
        "results/validation/methods_{law}.nc",
        law=config["validation"]["methods_per_law"]["laws"],
    )
    + [
        "results/validation/peer.nc",
        "results/validation/round_trip.nc",
        "results/validation/round_trip.csv",
    ]
)


rule validation_peer:
    """Last-cycle quantities of every law: switch solver vs CVODE (and the closed form), tolerances from config."""
    input:
        VALIDATION.table_paths(),
    output:
        csv=expand("results/validation/peer_{law}.csv", law=VALIDATION_LAWS),
        nc="results/validation/peer.nc",
    log:
        "results/logs/validation_peer/all.log",
    benchmark:
        "results/benchmarks/validation_peer/all.tsv"
    conda:
        CONDA_ENV
    params:
        validation={k: v for k, v in config["validation"].items() if k != "round_trip"},
    script:
        "../scripts/validation_peer.py"


rule validation_round_trip:
    """The 1-DOF model driven by the Fig. 17 table vs the cycle the table came from."""
    input:
        table="results/onedof/friction_mu_vr.csv",
        source=onedof_dataset(
            ONEDOF["friction_table"]["scene"],
            ONEDOF["friction_table"]["reading"],
            ONEDOF["friction_table"]["method"],
        ),
    output:
        nc="results/validation/round_trip.nc",
        csv="results/validation/round_trip.csv",
    log:
        "results/logs/validation_round_trip/all.log",
    benchmark:
        "results/benchmarks/validation_round_trip/all.tsv"
    conda:
        CONDA_ENV
    params:
        table=ONEDOF["friction_table"],
        onedof=onedof_subconfig(
            ONEDOF["friction_table"]["reading"],
            ONEDOF["friction_table"]["scene"],
            ONEDOF["friction_table"]["method"],
        ),
        validation={k: v for k, v in config["validation"].items() if k in ("solver", "round_trip")},
    script:
        "../scripts/validation_round_trip.py"


rule validation_methods:
    """Issue 13 item 5: the methods study on nonlinear laws, so the ranking is not an artefact of the affine one."""
    output:
        expand(
            "results/validation/methods_{law}.nc",
            law=config["validation"]["methods_per_law"]["laws"],
        ),
    log:
        "results/logs/validation_methods/all.log",
    benchmark:
        "results/benchmarks/validation_methods/all.tsv"
    conda:
        CONDA_ENV
    params:
        validation={
            k: v for k, v in config["validation"].items() if k not in ("round_trip", "peer", "tolerances")
        },
    script:
        "../scripts/validation_methods.py"
