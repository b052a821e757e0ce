# CalculiX (ccx) as a peer of the continuum strip, and the strip's input decks as a product (issue 28).
# Needs the `ccx` executable (Debian package calculix-ccx); without it the peer job fails naming ccx.

FE_PEER_DECKS = list(paths.FE_PEER_DECKS)


rule fe_peer_calculix:
    """Modes and self-weight states of the strip: closed form, continuum and CalculiX (C3D8I), with the
    relative differences and whether they agree; the two linear decks ccx ran."""
    output:
        **outputs("fe_peer_calculix"),
    log:
        paths.log("fe_peer_calculix", "peer"),
    benchmark:
        paths.benchmark("fe_peer_calculix", "peer")
    conda:
        CONDA_ENV
    params:
        # what the peer job reads: the strip (beam) and the peer's mesh and tolerance, nothing else of fe
        beam=canonical(FE_EFFECTIVE.defaults.beam.model_dump(exclude_none=True)),
        peer=canonical(FE_EFFECTIVE.peer.model_dump()),
        decks=FE_PEER_DECKS,  # the name of each deck output, in the same order
    script:
        "../scripts/fe_peer_calculix.py"


rule fe_decks:
    """Every Section 9-12 scene (default FE reading) as an ABAQUS/Explicit deck with the Fig. 17 friction
    table as its mu(slip rate) data, and as the CalculiX variant ccx runs (a translating block, penalty
    contact, one mu; stickslip.fe.ccx_deck)."""
    input:
        friction=FE_FRICTION,
    output:
        **outputs("fe_decks"),
    log:
        paths.log("fe_decks", "decks"),
    benchmark:
        paths.benchmark("fe_decks", "decks")
    conda:
        CONDA_ENV
    params:
        config=fe_job_config(FE_EFFECTIVE, scenes=FE_SCENES, sections=["comparison"]),
        scenes=FE_SCENES,  # the scene of each deck, in the same order
    script:
        "../scripts/fe_decks.py"


ALL_TARGETS.extend(products_of("fe_peer_calculix", "fe_decks"))
