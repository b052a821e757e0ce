"""Logging setup shared by the dense-map scripts (the map definitions live in stickslip.io.dense_map)."""

import logging

from stickslip.io.dense_map import dense_map  # noqa: F401  (re-exported for the scripts)


def log_to(snakemake) -> None:
    logging.basicConfig(
        filename=snakemake.log[0], level=logging.INFO, format="%(asctime)s %(message)s", force=True
    )
