"""Studies: typed specs in, datasets out. The layer between the science (model, solvers, analysis, fe) and the
wiring (workflow scripts): each function runs one kind of study and returns an xarray dataset, so a script
only resolves its spec, calls one function and writes the file."""
