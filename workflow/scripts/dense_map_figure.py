"""Thin wiring: one colour map per metric of a dense map; failed runs (solver_ok = 0 or NaN) are masked."""

import logging

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from dense_map_common import log_to  # noqa: E402

from stickslip.io.netcdf import read_dataset  # noqa: E402

log_to(snakemake)  # noqa: F821
ds = read_dataset(snakemake.input[0])  # noqa: F821
names = snakemake.params.plot  # noqa: F821
ydim, xdim = list(ds.solver_ok.dims)[:2] if ds.solver_ok.ndim >= 2 else (None, ds.solver_ok.dims[0])
failed = ds.solver_ok.values != 1
fig, axes = plt.subplots(
    1, len(names), figsize=(4.6 * len(names), 4.0), squeeze=False, constrained_layout=True
)
for ax, name in zip(axes[0], names):
    if name not in ds:
        raise KeyError(f"dense_map plot: {name!r} is not a metric of the map (have {sorted(ds.data_vars)})")
    var = ds[name]
    data = np.ma.masked_where(failed | ~np.isfinite(var.values), var.values)
    x, label_x = ds[xdim].values, f"{ds[xdim].long_name} [{ds[xdim].units}]"
    if ydim is None:
        ax.plot(x, data, "k.-")
        ax.set_ylabel(f"{var.long_name} [{var.units}]")
    else:
        # Colour limits from the 1st-99th percentile: a few runaway runs (the linear friction law changes
        # sign for |v_r| > 1/sigma) would otherwise flatten the map; arrows on the colour bar mark them.
        values = data.compressed()
        vmin, vmax = np.percentile(values, [1, 99]) if values.size else (0.0, 1.0)
        extend = {
            (False, False): "neither",
            (True, False): "min",
            (False, True): "max",
            (True, True): "both",
        }[(bool(values.size and values.min() < vmin), bool(values.size and values.max() > vmax))]
        norm = matplotlib.colors.Normalize(vmin, vmax)
        if values.size and values.min() > 0 and values.max() > 1e3 * values.min():  # spans decades: log scale
            norm, extend = matplotlib.colors.LogNorm(values.min(), values.max()), "neither"
        mesh = ax.pcolormesh(x, ds[ydim].values, data, shading="nearest", cmap="viridis", norm=norm)
        mesh.cmap.set_bad("0.85")  # no value (failed run, or no stick-slip): light grey
        fig.colorbar(mesh, ax=ax, label=f"[{var.units}]", extend=extend)
        ax.set_ylabel(f"{ds[ydim].long_name} [{ds[ydim].units}]")
        if failed.any():
            ax.contourf(
                x, ds[ydim].values, failed.astype(float), levels=[0.5, 1.5], colors="none", hatches=["xx"]
            )
    ax.set_xlabel(label_x)
    ax.set_title(var.long_name, fontsize=9)
    logging.info("%s: %d of %d points masked", name, int(np.ma.count_masked(data)), data.size)
fig.suptitle(
    f"{snakemake.params.title}\n{int(failed.sum())} failed runs masked (hatched); grey = no value",  # noqa: F821
    fontsize=10,
)
fig.savefig(snakemake.output[0], dpi=120)  # noqa: F821
