"""The beam on a rotating disc, numerics only: beam and continuum models, contact laws, explicit integration
(compiled kernels), reduced models, eigenvalue stability. Running scenes, sweeps and comparisons from config,
and building their datasets, is ``stickslip.studies.fe`` / ``stickslip.studies.fe_comparison``."""
