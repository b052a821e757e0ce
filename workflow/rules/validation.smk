# Issue 13: the switch-model solver for any friction law, checked against an independent program
# (SUNDIALS CVODE), the textbook Coulomb cycle, and the Fig. 17 round trip.
from stickslip.schema import LawMethodsJob, PeerJob
from stickslip.validation.setup import table_paths

#: The part of the section the peer job reads (its params, and its tables are inputs).
VALIDATION = as_written(CFG.validation)
VALIDATION_PEER = PeerJob.part_of(VALIDATION)

ALL_TARGETS.extend(products_of("validation_peer", "validation_methods", "validation_round_trip"))


rule validation_peer:
    """Last-cycle quantities of every law: switch solver vs CVODE (and the closed form), tolerances from config."""
    input:
        table_paths(PeerJob.model_validate(VALIDATION_PEER)),
    output:
        **outputs("validation_peer"),
    log:
        paths.log("validation_peer", "all"),
    benchmark:
        paths.benchmark("validation_peer", "all")
    conda:
        CONDA_ENV
    params:
        validation=VALIDATION_PEER,
    script:
        "../scripts/validation_peer.py"


rule validation_round_trip:
    """The 1-DOF model driven by the Fig. 17 table vs the cycle the table came from."""
    input:
        table=paths.friction_table("csv"),
        source=onedof_dataset(TABLE_RUN.scene, TABLE_RUN.reading, TABLE_RUN.method),
    output:
        **outputs("validation_round_trip"),
    log:
        paths.log("validation_round_trip", "all"),
    benchmark:
        paths.benchmark("validation_round_trip", "all")
    conda:
        CONDA_ENV
    params:
        table=as_params(TABLE_RUN),
        onedof=onedof_subconfig(TABLE_RUN.reading, TABLE_RUN.scene, TABLE_RUN.method),
        validation={k: v for k, v in VALIDATION.items() if k in ("solver", "round_trip")},
    script:
        "../scripts/validation_round_trip.py"


rule validation_methods:
    """Issue 13 item 5: the methods study on nonlinear laws, so the ranking is not an artefact of the affine one."""
    output:
        **outputs("validation_methods"),
    log:
        paths.log("validation_methods", "all"),
    benchmark:
        paths.benchmark("validation_methods", "all")
    conda:
        CONDA_ENV
    params:
        validation=LawMethodsJob.part_of(VALIDATION),
    script:
        "../scripts/validation_methods.py"
