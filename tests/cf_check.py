"""Offline CF compliance check of a netCDF file with the IOOS compliance-checker's CF suite."""

from __future__ import annotations

import warnings

CF_SUITE = "cf:1.10"

#: Checks of geographic grids (latitude/longitude, reduced horizontal grids). The datasets have no
#: geographic coordinates, so these find nothing to check; they search every variable against every
#: other, which on a dataset with ~80 variables (metrics and their ensembles) was 2/3 of the checker's time.
SKIP_CHECKS = ["check_grid_coordinates", "check_reduced_horizontal_grid"]


def _failed(result) -> bool:
    value = result.value
    if isinstance(value, tuple):
        return value[0] < value[1]
    return value is False


def _cache_geophysical_variables() -> None:
    """compliance-checker looks its geophysical-variable cache up by the dataset but fills it by the
    dataset's string, so it never hits: seven checks each search every variable against every other (12 of
    16 s on a beam-on-disc scene with ~200 variables). The same search, cached under one key."""
    from compliance_checker.cf import util as cfutil
    from compliance_checker.cf.cf_base import CFBaseCheck

    def find(self, ds, refresh=False):
        key = ds.__str__()
        if refresh or key not in self._geophysical_vars:
            self._geophysical_vars[key] = cfutil.get_geophysical_variables(ds)
        return self._geophysical_vars[key]

    CFBaseCheck._find_geophysical_vars = find


def cf_findings(path, min_weight: int = 2) -> list[str]:
    """Failed CF checks of weight >= ``min_weight`` (3 = high / "must", 2 = medium / "should")."""
    from compliance_checker.suite import CheckSuite

    _cache_geophysical_variables()

    suite = CheckSuite()
    suite.load_all_available_checkers()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = suite.load_dataset(str(path))
        groups, errors = suite.run_all(ds, [CF_SUITE], skip_checks=SKIP_CHECKS)[CF_SUITE]
    out = [f"checker error {name}: {err}" for name, err in errors.items()]
    for result in groups:
        if result.weight >= min_weight and _failed(result):
            out.append(f"[{result.weight}] {result.name}: {'; '.join(result.msgs)}")
    return out
