"""Report captions: paper figures parsed from claim rows, one Jinja template rendering per output."""

import jinja2

from stickslip.presentation.report import caption_template, caption_text, claims_for, paper_figures


def test_paper_figures():
    assert paper_figures("Fig. 2-3") == {2, 3}
    assert paper_figures("Fig. 21/24") == {21, 24}
    assert paper_figures("Fig. 21 vs Fig. 23") == {21, 23}
    assert paper_figures("Fig. 33 (ODB header)") == {33}
    assert paper_figures("Fig. 2 (restated)") == {2}
    assert paper_figures("") == set()


ROWS = [
    {
        "claim": "a",
        "reading": "r1",
        "figure": "Fig. 2",
        "status": "reproduced",
        "expected": "reproduced",
        "matches_expected": "True",
        "reason": "",
    },
    {
        "claim": "b",
        "reading": "r2",
        "figure": "Fig. 2-3",
        "status": "deviates",
        "expected": "deviates",
        "matches_expected": "True",
        "reason": "measured 1 vs reported 2",
    },
    {
        "claim": "c",
        "reading": "r1",
        "figure": "Fig. 21",
        "status": "not-comparable",
        "expected": "reproduced",
        "matches_expected": "False",
        "reason": "solver failed (x.nc: step size collapsed)",
    },
]


def test_claims_for_filters_by_figure_and_reading():
    assert [r["claim"] for r in claims_for(ROWS, {2})] == ["a", "b"]
    assert [r["claim"] for r in claims_for(ROWS, {3}, "r2")] == ["b"]
    assert [r["claim"] for r in claims_for(ROWS, {2}, "r1")] == ["a"]


def test_caption_names_figures_statuses_and_failed_runs():
    text = caption_text("FE scene", {21}, claims_for(ROWS, {21}))
    assert "Shows: Fig. 21." in text
    assert "1 not-comparable (1 on a failed solver run)" in text
    assert "(pinned reproduced)" in text


def test_template_selects_the_caption_of_the_rendered_output():
    template = caption_template({"results/a.png": "caption A {{ not jinja }}", "results/b.png": "caption B"})
    env = jinja2.Environment(trim_blocks=True, lstrip_blocks=True)  # as snakemake's report renders captions

    class Job:
        def __init__(self, out):
            self.output = [out]

    assert env.from_string(template).render(snakemake=Job("results/b.png")).strip() == "caption B"
    assert "caption A {{ not jinja }}" in env.from_string(template).render(snakemake=Job("results/a.png"))
    assert "No caption" in env.from_string(template).render(snakemake=Job("results/c.png"))


def test_caption_counts_every_status_and_explains_indistinguishable():
    rows = [
        dict(ROWS[0], margin="0.2", spread="0.01"),
        dict(
            ROWS[1],
            status="indistinguishable",
            expected="indistinguishable",
            margin="1e-9",
            spread="4e-9",
        ),
    ]
    text = caption_text("Fig. 2", {2}, rows)
    assert "Claims: 1 reproduced, 0 deviates, 1 indistinguishable, 0 not-comparable." in text
    assert "within 3x its perturbation-ensemble spread" in text
    assert "``a`` [r1]: **reproduced** (margin 0.2, spread 0.01)" in text
    assert "``b`` [r2]: **indistinguishable** (margin 1e-09, spread 4e-09)" in text
    stated = dict(rows[1], reason="margin 1e-09 <= 3 x spread 4e-09: below the numerical noise")
    assert caption_text("Fig. 2", {2}, [stated]).count("margin 1e-09") == 1  # not repeated


def test_caption_without_ensemble_or_margin_says_so():
    no_ensemble = dict(ROWS[0], margin="0.2", spread="nan")
    no_margin = dict(ROWS[2], margin="", spread="")
    text = caption_text("x", {2, 21}, [no_ensemble, no_margin])
    assert "**reproduced** (margin 0.2, no ensemble)" in text
    assert "**not-comparable** (pinned reproduced) — solver failed" in text
    assert "Indistinguishable:" not in text  # the note appears only when a row is indistinguishable
