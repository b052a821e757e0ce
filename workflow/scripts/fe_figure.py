"""Plot one scene dataset (displacements, velocities, forces, contact state) -> PNG."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import xarray as xr  # noqa: E402

from fe_common import log_to  # noqa: E402

log_to(snakemake)  # noqa: F821
ds = xr.load_dataset(snakemake.input[0])  # noqa: F821
fig, ax = plt.subplots(4, 1, figsize=(8, 9), sharex=True)
for a, names in zip(
    ax,
    (
        ("horizontal_displacement", "vertical_displacement"),
        ("horizontal_velocity", "vertical_velocity"),
        ("normal_force", "friction_force"),
        ("contact_state",),
    ),
):
    for n in names:
        ds[n].plot(ax=a, label=n, lw=0.6)
    a.legend(fontsize=7)
    a.set_title("")
ax[0].set_title(ds.attrs.get("title", ""))
fig.tight_layout()
fig.savefig(snakemake.output[0], dpi=110)  # noqa: F821
