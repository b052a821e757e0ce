"""Moved to ``stickslip.catalogue`` (the bottom of the package, so science and claims may look paths up too).

Kept as a re-export so that branches written against the old import path still run; new code imports
``stickslip.catalogue``.
"""

from ..catalogue import onedof_catalogue, onedof_dataset, sweep_dataset  # noqa: F401
