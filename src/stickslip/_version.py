"""The package version, in a module of its own: a module that records it (``io.netcdf``) imports it from
here, not from the package, whose ``__init__`` loads the public API by name (``stickslip.pipeline.code_deps``
would count every module the API reaches as that module's code)."""

__version__ = "0.1.0"
