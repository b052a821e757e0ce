"""Figures draw from datasets (presentation code is still code)."""

def test_moved_notebook_helpers_still_import_from_plots():
    """Notebooks written for the old layout (``from stickslip.plots import claims_frame``) keep working."""
    import pytest

    from stickslip import notebook, plots
    from stickslip.plots import claims_frame, reported_value, status_counts, styled_claims

    assert claims_frame is notebook.claims_frame and styled_claims is notebook.styled_claims
    assert status_counts is notebook.status_counts and reported_value is notebook.reported_value
    assert plots.claims_readings is notebook.claims_readings
    with pytest.raises(AttributeError, match="no_such_helper"):
        plots.no_such_helper  # noqa: B018
