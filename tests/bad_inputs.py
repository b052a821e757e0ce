"""The bad-input matrix: broken configs, files and claims rows, each with the words its error must name.

Every config case is an override merged over config/*.yaml and the small CI config, as a user's
``--configfile`` would be; every claims case is a broken claims file. tests/pipeline/test_config_errors.py
runs the config cases through ``stickslip.pipeline.config.validate_config`` (what the Snakefile calls at parse
time), tests/claims/test_claims_errors.py the claims cases through the claims loader and check, and
tests/end_to_end/test_bad_input.py a few of each through the real pipeline.
"""

from stickslip.pipeline.config import load_config

from project_run import ROOT

CASES = {
    # id: (override config, words the message must contain)
    "mass_negative": ({"onedof": {"defaults": {"params": {"mass": -1.0}}}}, ["mass"]),
    "mass_zero": ({"onedof": {"defaults": {"params": {"mass": 0.0}}}}, ["mass"]),
    "stiffness_zero": ({"onedof": {"scenes": {"fig02": {"params": {"stiffness": 0.0}}}}}, ["stiffness"]),
    "stiffness_negative": ({"onedof": {"scenes": {"fig02": {"params": {"stiffness": -5.0}}}}}, ["stiffness"]),
    "stiffness_nan": (
        {"onedof": {"scenes": {"fig02": {"params": {"stiffness": float("nan")}}}}},
        ["stiffness"],
    ),
    "mass_inf": ({"onedof": {"defaults": {"params": {"mass": float("inf")}}}}, ["mass"]),
    "stiffness_string": ({"onedof": {"defaults": {"params": {"stiffness": "five"}}}}, ["stiffness", "five"]),
    "t_end_string": ({"onedof": {"defaults": {"t_end": "long"}}}, ["t_end"]),
    "t_end_nan": ({"onedof": {"defaults": {"t_end": float("nan")}}}, ["t_end"]),
    "readings_not_a_list": (
        {"onedof": {"figures": {"fig02": {"readings": "consistent_caption"}}}},
        ["readings"],
    ),
    "unknown_method": ({"onedof": {"figures": {"fig02": {"methods": ["exact", "rk99"]}}}}, ["rk99"]),
    "unknown_solver": ({"onedof": {"methods": {"ode45": {"solver": "nosuch"}}}}, ["nosuch"]),
    "unknown_scene": ({"onedof": {"figures": {"fig02": {"scene": "fig99"}}}}, ["fig99"]),
    "unknown_reading": ({"onedof": {"figures": {"fig02": {"readings": ["eq9_text"]}}}}, ["eq9_text"]),
    "unknown_claims_reading": ({"claims": {"readings": ["eq9_text"]}}, ["claims.readings", "eq9_text"]),
    "unknown_variant": ({"onedof": {"readings": {"eq3_text": {"variant": "eq5_printed"}}}}, ["variant"]),
    "missing_friction_table": (
        {"fe": {"friction_table": "results/onedof/no_such_table.csv"}},
        ["fe.friction_table", "no_such_table.csv"],
    ),
    "friction_table_not_a_table": (
        {"fe": {"friction_table": "/etc/passwd"}},
        ["fe.friction_table", "/etc/passwd", "relative_velocity_mm_per_s,mu"],
    ),
    "friction_table_speeds_not_increasing": (
        {"fe": {"friction_table": str(ROOT / "tests" / "data" / "friction_table_not_monotone.csv")}},
        ["fe.friction_table", "friction_table_not_monotone.csv", "line 4", "must increase"],
    ),
    "fe_negative_modulus": (
        {"fe": {"defaults": {"beam": {"youngs_modulus_gpa": -210.0}}}},
        ["youngs_modulus_gpa"],
    ),
    "fe_nan_t_end": ({"fe": {"defaults": {"solver": {"t_end": float("nan")}}}}, ["t_end"]),
    "fe_unknown_sweep_base": (
        {"fe": {"sweeps": {"angle_sweep": {"base": "no_scene"}}}},
        ["fe.sweeps.angle_sweep.base"],
    ),
    "methods_negative_mass": ({"methods_study": {"base_params": {"mass": -1.0}}}, ["mass"]),
    "methods_negative_eta": (
        {"methods_study": {"methods": [{"solver": "karnopp", "sweep": {"eta": [1.0e-3, -1.0]}}]}},
        ["methods_study.methods", "eta"],
    ),
    "ode45_negative_rtol": ({"onedof": {"methods": {"ode45": {"rtol": -1.0e-3}}}}, ["ode45", "rtol"]),
    "ensemble_bad_relative": ({"ensemble": {"relative": 0.5}}, ["ensemble", "relative"]),
    # the ensemble's own spec (what every job builds) refuses 1e-3: the config check must too
    "ensemble_relative_at_the_jobs_limit": ({"ensemble": {"relative": 1.0e-3}}, ["ensemble", "relative"]),
    "ensemble_seeds_empty": ({"ensemble": {"seeds": []}}, ["ensemble.seeds"]),
    "ensemble_step_factor_above_one": ({"ensemble": {"step_factor": 1.5}}, ["ensemble.step_factor"]),
    "ensemble_step_factor_one": ({"ensemble": {"step_factor": 1.0}}, ["ensemble.step_factor"]),
    # a scene's own parameters, named with their full key
    "scene_mass_nan": (
        {"onedof": {"scenes": {"fig02": {"params": {"mass": float("nan")}}}}},
        ["onedof.scenes.fig02.params.mass"],
    ),
    # strict: no string for a number, even one that reads as a number
    "scene_mass_numeric_string": (
        {"onedof": {"scenes": {"fig02": {"params": {"mass": "1.0"}}}}},
        ["onedof.scenes.fig02.params.mass"],
    ),
    "scene_params_typo": (
        {"onedof": {"scenes": {"fig02": {"params": {"masss": 1.0}}}}},
        ["onedof.scenes.fig02.params.masss"],
    ),
    "reading_variant_unknown": (
        {"onedof": {"readings": {"consistent_caption": {"variant": "eq5"}}}},
        ["variant"],
    ),
    "ode45_option_typo": ({"onedof": {"methods": {"ode45": {"rtoll": 1.0e-3}}}}, ["rtoll"]),
    "sweep_parameter_typo": (
        {"onedof": {"sweeps": {"fig12": {"parameter": "dampening"}}}},
        ["fig12.parameter"],
    ),
    "sweep_dense_start_past_the_values": (
        {"onedof": {"sweeps": {"fig12": {"dense": {"start": 9.0}}}}},
        ["fig12.dense"],
    ),
    "sweep_linked_typo": (
        {"onedof": {"sweeps": {"fig14": {"linked": {"normal_farce": 10.0}}}}},
        ["fig14.linked"],
    ),
    "sweep_values_negative": ({"onedof": {"sweeps": {"fig12": {"values": [-1.0, 1.0]}}}}, ["fig12.values"]),
    "dense_map_no_axes": (
        {"dense_map": {"maps": {"speed_damping": {"axes": []}}}},
        ["dense_map.maps.speed_damping.axes"],
    ),
    "failure_map_unknown_solver": (
        {"methods_study": {"failure_map": {"methods": [{"solver": "rk99"}]}}},
        ["methods_study.failure_map.methods", "rk99"],
    ),
    # unknown or misspelt keys, in every config file's sections
    "top_level_typo": ({"onedoff": {}}, ["onedoff"]),
    "baseline_unknown_scene": (
        {"onedof": {"baseline": {"scene": "fig99"}}},
        ["onedof.baseline.scene", "fig99"],
    ),
    "baseline_unknown_method": (
        {"onedof": {"baseline": {"method": "rk99"}}},
        ["onedof.baseline.method", "rk99"],
    ),
    "onedof_defaults_typo": ({"onedof": {"defaults": {"t_ende": 1.0}}}, ["onedof.defaults.t_ende"]),
    "figure_plot_key_typo": ({"onedof": {"figures": {"fig03": {"plott": "phase"}}}}, ["fig03.plott"]),
    "figure_plot_value_typo": ({"onedof": {"figures": {"fig03": {"plot": "phse"}}}}, ["fig03.plot"]),
    "sweep_figure_typo": ({"onedof": {"sweep_figures": {"fig10": {"readngs": ["x"]}}}}, ["readngs"]),
    # the paper-figure maps the catalogue reads: figures of the paper, scenes of the config
    "figure_paper_figure_not_in_the_paper": (
        {"onedof": {"figures": {"fig02": {"paper_figures": [37]}}}},
        ["onedof.figures.fig02.paper_figures"],
    ),
    "fe_paper_figure_unknown_scene": (
        {"fe": {"paper_figures": {21: ["section9_kinematic"]}}},
        ["fe.paper_figures.21", "section9_kinematic"],
    ),
    "fe_paper_figure_not_beam_on_disc": (
        {"fe": {"paper_figures": {20: ["section9_kinematic_15p2rpm"]}}},
        ["fe.paper_figures", "20"],
    ),
    "notebook_key_typo": ({"notebooks": {"section_03_baseline": {"figurs": ["fig02"]}}}, ["figurs"]),
    "claims_section_typo": ({"claims": {"cheque": True}}, ["claims.cheque"]),
    "claims_check_not_bool": ({"claims": {"check": "yes"}}, ["claims.check"]),
    "claims_readings_empty": ({"claims": {"readings": []}}, ["claims.readings"]),
    "fe_beam_typo": ({"fe": {"defaults": {"beam": {"lenght": 100.0}}}}, ["lenght"]),
    "methods_typo": ({"methods_study": {"budgett": {}}}, ["budgett"]),
    "inverse_typo": ({"inverse": {"figurs": {}}}, ["figurs"]),
    "validation_typo": ({"validation": {"tolerances": {"tim": {}}}}, ["tim"]),
    "dense_map_typo": ({"dense_map": {"chunk_sise": 10}}, ["chunk_sise"]),
    "fe_long_runs_not_bool": ({"fe_long_runs": "yes"}, ["fe_long_runs"]),
    "fe_control_window_negative": ({"fe": {"control_readings_t_end": -0.1}}, ["fe.control_readings_t_end"]),
    # a control reading's window shorter than its output interval: named with the reading
    "fe_control_window_below_output_dt": (
        {"fe": {"control_readings_t_end": 1.0e-6}},
        ["lower_face_static", "solver.output_dt"],
    ),
    "allow_expensive_not_bool": ({"allow_expensive": "yes"}, ["allow_expensive"]),
    # run lengths that do not fit in their run (1-DOF, studies)
    "onedof_output_dt_beyond_t_end": (
        {"onedof": {"defaults": {"output_dt": 1.0e6}}},
        ["onedof.defaults.output_dt"],
    ),
    "onedof_transient_beyond_t_end": (
        {"onedof": {"scenes": {"fig02": {"transient": 1.0e6}}}},
        ["onedof.scenes.fig02.transient", "t_end"],
    ),
    "onedof_count_window_beyond_t_end": (
        {"onedof": {"scenes": {"fig02": {"count_window": 1.0e6}}}},
        ["onedof.scenes.fig02.count_window"],
    ),
    "reading_output_dt_beyond_t_end": (
        {"onedof": {"readings": {"consistent_caption": {"output_dt": 1.0e6}}}},
        ["onedof.readings.consistent_caption.output_dt"],
    ),
    "scene_t_end_shorter_than_default_transient": (
        {"onedof": {"scenes": {"fig05": {"t_end": 1.0}}}},
        ["onedof.defaults.transient", "onedof.scenes.fig05.t_end"],
    ),
    "critical_speed_transient_beyond_t_end": (
        {"onedof": {"critical_speed": {"transient": 1.0e6}}},
        ["onedof.critical_speed", "transient"],
    ),
    "methods_output_dt_beyond_t_end": ({"methods_study": {"output_dt": 1.0e6}}, ["methods_study.output_dt"]),
    "validation_output_dt_beyond_t_end": (
        {"validation": {"methods_per_law": {"output_dt": 1.0e6}}},
        ["validation.methods_per_law.output_dt"],
    ),
    "fe_output_dt_beyond_t_end": (
        {"fe": {"defaults": {"solver": {"output_dt": 10.0}}}},
        ["solver.output_dt"],
    ),
    "fe_bin_width_beyond_t_end": (
        {"fe": {"defaults": {"output": {"bin_width": 10.0}}}},
        ["output.bin_width"],
    ),
    "fe_window_beyond_t_end": (
        {"fe": {"defaults": {"output": {"windows": [[0.0, 10.0]]}}}},
        ["output.windows[0]"],
    ),
    # ranges that run backwards
    "critical_speed_backwards": (
        {"onedof": {"critical_speed": {"start": 2.0, "stop": 0.5}}},
        ["onedof.critical_speed", "start < stop"],
    ),
    "sweep_dense_backwards": (
        {"onedof": {"sweeps": {"fig10": {"dense": {"start": 0.9, "stop": 0.2, "num": 4}}}}},
        ["onedof.sweeps.fig10.dense", "start < stop"],
    ),
    "dense_map_axis_backwards": (
        {
            "dense_map": {
                "maps": {
                    "speed_damping": {"axes": [{"name": "damping", "start": 2.0, "stop": 0.5, "num": 4}]}
                }
            }
        },
        ["dense_map.maps.speed_damping.axes", "start < stop"],
    ),
    "fe_window_backwards": ({"fe": {"defaults": {"output": {"windows": [[0.05, 0.01]]}}}}, ["windows[0]"]),
    "inverse_bound_backwards": (
        {"inverse": {"bounds": {"damping": {"min": 5.0, "max": 0.5, "reason": "r"}}}},
        ["inverse.bounds.damping", "min < max"],
    ),
    "inverse_mu_k_ratio_backwards": (
        {"inverse": {"hypotheses": {"mu_k": {"mu_k_ratio": {"min": 1.0, "max": 0.3}}}}},
        ["inverse.hypotheses.mu_k.mu_k_ratio", "min < max"],
    ),
    "methods_timing_repeats_backwards": (
        {"methods_study": {"timing": {"min_repeats": 9, "max_repeats": 2}}},
        ["methods_study.timing", "min_repeats"],
    ),
    # sizes: reported with their estimate, lifted only by allow_expensive
    "sweep_of_a_billion_points": (
        {"onedof": {"sweeps": {"fig10": {"dense": {"start": 0.2, "stop": 0.9, "num": 1_000_000_000}}}}},
        ["onedof.sweeps.fig10.dense.num", "allow_expensive"],
    ),
    "dense_map_of_a_billion_points": (
        {
            "dense_map": {
                "max_chunks": 10**9,
                "maps": {
                    "speed_damping": {"axes": [{"name": "damping", "start": 0.5, "stop": 2.0, "num": 10**9}]}
                },
            }
        },
        ["dense_map.maps.speed_damping.axes", "allow_expensive"],
    ),
    "onedof_run_of_a_billion_samples": (
        {"onedof": {"defaults": {"output_dt": 1.0e-8}}},
        ["samples per run", "allow_expensive"],
    ),
    "fe_mesh_of_a_billion_elements": (
        {"fe": {"defaults": {"beam": {"n_elements": 1_000_000_000}}}},
        ["fe.defaults.beam.n_elements", "allow_expensive"],
    ),
    "fe_continuum_mesh_too_large": ({"fe": {"comparison": {"mesh": [100000, 100]}}}, ["fe.comparison.mesh"]),
    "fe_increments_mesh_too_large": (
        {"fe": {"increments": {"meshes": [[100000, 100]]}}},
        ["fe.increments.meshes[0]"],
    ),
    "fe_convergence_mesh_too_large": (
        {"fe": {"convergence": {"n_elements": [20, 10**7]}}},
        ["fe.convergence.n_elements"],
    ),
    "fe_long_window_with_a_fine_mesh": (
        {"fe": {"defaults": {"beam": {"n_elements": 10000}, "solver": {"t_end": 10.0}}}},
        ["n_elements", "element-increments", "allow_expensive"],
    ),
    # physics and references, per section
    "fe_poisson_half": ({"fe": {"defaults": {"beam": {"poisson_ratio": 0.5}}}}, ["poisson_ratio"]),
    "fe_angle_ninety": (
        {"fe": {"scenes": {"section12_angle30_15p2rpm": {"contact": {"angle_deg": 90.0}}}}},
        ["angle_deg"],
    ),
    "fe_negative_disc_speed": (
        {"fe": {"defaults": {"disc": {"speed_rev_per_min": -1.0}}}},
        ["speed_rev_per_min"],
    ),
    "fe_unknown_contact_method": ({"fe": {"defaults": {"contact": {"method": "glue"}}}}, ["contact.method"]),
    "sweep_unknown_parameter": ({"onedof": {"sweeps": {"fig10": {"parameter": "massa"}}}}, ["massa"]),
    "eq6_too_few_points": ({"onedof": {"eq6": {"points": 5}}}, ["onedof.eq6.points"]),
    "friction_table_one_bin": ({"onedof": {"friction_table": {"bins": 1}}}, ["onedof.friction_table.bins"]),
    "dense_map_unknown_reading": (
        {"dense_map": {"maps": {"speed_damping": {"reading": "eq9_text"}}}},
        ["dense_map.maps.speed_damping.reading", "eq9_text"],
    ),
    "dense_map_chunk_zero": ({"dense_map": {"chunk_size": 0}}, ["dense_map.chunk_size"]),
    "notebook_unknown_figure": ({"notebooks": {"section_03_baseline": {"figures": ["fig99"]}}}, ["fig99"]),
    "inverse_unknown_claim": (
        {"inverse": {"figures": {"fig02": {"claims": ["s3_no_such_claim"]}}}},
        ["inverse.figures.fig02.claims", "s3_no_such_claim"],
    ),
    "inverse_scene_and_sweep": (
        {"inverse": {"figures": {"fig02": {"sweep": "fig12"}}}},
        ["inverse.figures.fig02", "exactly one"],
    ),
    "inverse_one_walker": ({"inverse": {"settings": {"default": {"walkers": 1}}}}, ["walkers"]),
    "validation_unknown_peer_method": (
        {"validation": {"peer": {"method": "RK"}}},
        ["validation.peer.method"],
    ),
    "validation_unknown_law": ({"validation": {"methods_per_law": {"laws": ["no_law"]}}}, ["no_law"]),
    "methods_failure_map_unknown_scene": (
        {"methods_study": {"failure_map": {"scene": "no_scene"}}},
        ["methods_study.failure_map", "no_scene"],
    ),
    # issue 29: inputs that passed before
    "fe_sweep_parameter_typo": (
        {"fe": {"sweeps": {"angle_sweep": {"parameter": "contact.angel_deg"}}}},
        ["fe.sweeps.angle_sweep.parameter", "angel_deg", "angle_deg"],
    ),
    "fe_sweep_parameter_not_a_number": (
        {"fe": {"sweeps": {"angle_sweep": {"parameter": "contact.method"}}}},
        ["fe.sweeps.angle_sweep.parameter", "method"],
    ),
    "fe_output_dt_stores_every_step": (
        {"fe": {"defaults": {"solver": {"output_dt": 1.0e-15}}}},
        ["fe.defaults.solver.output_dt", "samples"],
    ),
    "fe_scene_output_dt_stores_every_step": (
        {"fe": {"scenes": {"section9_kinematic_0p5mm_s": {"solver": {"output_dt": 1.0e-12}}}}},
        ["fe.scenes.section9_kinematic_0p5mm_s.solver.output_dt", "samples"],
    ),
    "fe_sweep_window_shorter_than_output_dt": (
        {"fe": {"sweeps": {"angle_sweep": {"t_end": 1.0e-6}}}},
        ["fe.sweeps.angle_sweep.t_end", "output_dt"],
    ),
    "fe_convergence_window_shorter_than_output_dt": (
        {"fe": {"convergence": {"t_end": 1.0e-6}}},
        ["fe.convergence.t_end"],
    ),
    "fe_comparison_window_shorter_than_output_dt": (
        {"fe": {"comparison": {"t_end": 1.0e-6}}},
        ["fe.comparison.t_end"],
    ),
    "fe_stability_slope_huge": ({"fe": {"stability": {"slopes": [-1.0e300]}}}, ["fe.stability.slopes[0]"]),
    "fe_crosscheck_slope_huge": (
        {"fe": {"stability": {"crosscheck": [[0.0, 1.0e3]]}}},
        ["fe.stability.crosscheck", "crosscheck[0][1]"],
    ),
}

ALIAS_BOMB = "bomb:\n  a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"  {n}: &{n} [{', '.join([f'*{p}'] * 10)}]\n" for p, n in zip("abcdefgh", "bcdefghi")
)

#: Whole files that cannot be read as data: (file under config/, text, words the message must contain).
BAD_FILES = {
    **{
        f"syntax_error_in_{name}": (
            f"{name}.yaml",
            "onedof:\n  defaults: [1, 2\n  other: 3\n",
            [f"{name}.yaml:3"],
        )
        for name in ("config", "fe", "methods", "inverse", "dense_map", "validation")
    },
    **{
        f"duplicate_key_in_{name}": (
            f"{name}.yaml",
            "ensemble:\n  seeds: [1, 2]\n  seeds: [3, 4]\n",
            [f"{name}.yaml:3", "duplicate key 'seeds'"],
        )
        for name in ("config", "fe", "methods", "inverse", "dense_map", "validation")
    },
    "template_key_in_a_config_file": (
        "zz_extra.yaml",
        "__use_yte__: true\nensemble: {seeds: [1]}\n",
        ["__use_yte__"],
    ),
    "a_list_instead_of_sections": ("zz_extra.yaml", "- onedof\n- fe\n", ["zz_extra.yaml", "mapping"]),
    "tab_indented": ("zz_extra.yaml", "ensemble:\n\tseeds: [1]\n", ["zz_extra.yaml:2"]),
    # a "billion laughs": nine lines of aliases expanding to 10^9 nodes (issue 29: ran to MemoryError)
    # named at the entry that expands beyond the limit (bomb.f, line 7), not at the first alias of the file
    "alias_bomb": ("zz_extra.yaml", ALIAS_BOMB, ["zz_extra.yaml:7", "bomb.f:", "aliases", "expand"]),
    "alias_bomb_in_a_real_key": (
        "zz_extra.yaml",
        ALIAS_BOMB.replace("bomb:", "ensemble:\n  seeds:\n   - x:"),
        ["zz_extra.yaml:", "aliases"],
    ),
}

BAD_CLAIMS = {
    "claims_missing_key": (
        [{"id": "x1", "section": "3", "figure": "Fig. 2", "kind": "value"}],
        ["x1", "quote: Field required"],
    ),
    "claims_bad_kind": (
        [
            {
                "id": "x2",
                "section": "3",
                "figure": "Fig. 2",
                "quote": "q",
                "kind": "guess",
                "expected": "reproduced",
            }
        ],
        ["x2", "kind"],
    ),
    "claims_bad_status": (
        [
            {
                "id": "x3",
                "section": "3",
                "figure": "Fig. 2",
                "quote": "q",
                "kind": "value",
                "expected": "maybe",
            }
        ],
        ["x3", "maybe"],
    ),
}

#: A valid row of each kind; the cases below break one key of one of them.
VALUE_ROW = {
    "evidence": "evidence",
    "id": "zz_value",
    "section": "3",
    "figure": "Fig. 2",
    "figures": [2],
    "quote": "q",
    "kind": "value",
    "dataset": "results/onedof/fig02/{reading}/exact.nc",
    "variable": "max_displacement",
    "value": 1.5,
    "unit": "mm",
    "tolerance": {"rel": 0.1, "reason": "read off a plotted curve"},
    "expected": "deviates",
}
COMPARE_ROW = {
    "evidence": "evidence",
    "id": "zz_compare",
    "section": "5",
    "figure": "Fig. 5 vs 2",
    "figures": [5, 2],
    "quote": "q",
    "kind": "compare",
    "lhs": {"dataset": "results/onedof/fig05/{reading}/exact.nc", "variable": "max_displacement"},
    "rhs": {"dataset": "results/onedof/fig02/{reading}/exact.nc", "variable": "max_displacement"},
    "relation": ">",
    "expected": "reproduced",
}
TREND_ROW = {
    "evidence": "evidence",
    "id": "zz_trend",
    "section": "5",
    "figure": "Fig. 10",
    "figures": [10],
    "quote": "q",
    "kind": "trend",
    "dataset": "results/onedof/sweeps/fig10_dense/{reading}.nc",
    "variable": "frequency_peaks",
    "coord": "mu_s",
    "sign": -1,
    "expected": "reproduced",
}


def _with(row, **changes):
    out = {**row, **changes}
    return {k: v for k, v in out.items() if v is not None}


def _without(row, key):
    return {k: v for k, v in row.items() if k != key}


BAD_CLAIMS.update(
    {
        "claims_tolerance_typo": (
            [_with(_without(VALUE_ROW, "tolerance"), tolerence={"rel": 0.1, "reason": "r"})],
            ["zz_value", "tolerence"],
        ),
        "claims_negative_tolerance": (
            [_with(VALUE_ROW, tolerance={"rel": -0.1, "reason": "r"})],
            ["zz_value", "tolerance.rel"],
        ),
        "claims_tolerance_above_100_percent": (
            [_with(VALUE_ROW, tolerance={"rel": 1.0e9, "reason": "r"})],
            ["zz_value", "tolerance.rel"],
        ),
        "claims_tolerance_without_reason": (
            [_with(VALUE_ROW, tolerance={"rel": 0.1})],
            ["zz_value", "tolerance.reason"],
        ),
        "claims_tolerance_without_width": (
            [_with(VALUE_ROW, tolerance={"reason": "r"})],
            ["zz_value", "tolerance", "rel or abs"],
        ),
        "claims_value_with_unit_text": ([_with(VALUE_ROW, value="1.5 mm")], ["zz_value", "value", "1.5 mm"]),
        "claims_value_nan": ([_with(VALUE_ROW, value=float("nan"))], ["zz_value", "value"]),
        "claims_value_without_variable": ([_without(VALUE_ROW, "variable")], ["zz_value", "variable"]),
        "claims_value_without_unit": ([_without(VALUE_ROW, "unit")], ["zz_value", "unit"]),
        "claims_value_with_a_relation": ([_with(VALUE_ROW, relation=">")], ["zz_value", "relation"]),
        "claims_unknown_key": ([_with(VALUE_ROW, comparble=False)], ["zz_value", "comparble"]),
        "claims_fit_flag_as_text": ([_with(VALUE_ROW, fit="yes")], ["zz_value", "fit"]),
        "claims_evidence_class_missing": ([_without(VALUE_ROW, "evidence")], ["zz_value", "evidence"]),
        "claims_evidence_class_unknown": ([_with(VALUE_ROW, evidence="proof")], ["zz_value", "evidence"]),
        "claims_not_evidence_without_why": (
            [_with(VALUE_ROW, evidence="by_construction")],
            ["zz_value", "evidence_note"],
        ),
        "claims_evidence_with_a_why_not": (
            [_with(VALUE_ROW, evidence_note="it cannot fail")],
            ["zz_value", "evidence_note"],
        ),
        "claims_twin_and_one_speed": (
            [_with(VALUE_ROW, twin="zz_other", one_speed="why")],
            ["zz_value", "one_speed"],
        ),
        "claims_figure_not_in_the_paper": ([_with(VALUE_ROW, figures=[99])], ["zz_value", "figures", "99"]),
        "claims_figures_as_text": ([_with(VALUE_ROW, figures="2")], ["zz_value", "figures"]),
        "claims_figures_missing": ([_without(VALUE_ROW, "figures")], ["zz_value", "figures"]),
        "claims_figure_listed_twice": ([_with(VALUE_ROW, figures=[2, 2])], ["zz_value", "figures"]),
        "claims_id_with_spaces": ([_with(VALUE_ROW, id="zz value")], ["zz value", "id"]),
        "claims_quote_empty": ([_with(VALUE_ROW, quote="")], ["zz_value", "quote"]),
        "claims_pinned_status_per_reading_typo": (
            [_with(VALUE_ROW, expected={"default": "deviates", "consistent_caption": "reproducd"})],
            ["zz_value", "reproducd"],
        ),
        "claims_compare_bad_relation": ([_with(COMPARE_ROW, relation="=>")], ["zz_compare", "relation"]),
        "claims_compare_with_tolerance": (
            [_with(COMPARE_ROW, tolerance={"rel": 0.1, "reason": "r"})],
            ["zz_compare", "tolerance"],
        ),
        "claims_compare_without_rhs": ([_without(COMPARE_ROW, "rhs")], ["zz_compare", "rhs"]),
        "claims_operand_with_value_and_dataset": (
            [
                _with(
                    COMPARE_ROW,
                    rhs={"dataset": "results/onedof/fig02/{reading}/exact.nc", "variable": "x", "value": 1.0},
                )
            ],
            ["zz_compare", "rhs"],
        ),
        "claims_operand_typo": (
            [_with(COMPARE_ROW, lhs={"datset": "a.nc", "variable": "x"})],
            ["zz_compare", "datset"],
        ),
        "claims_ratio_without_value": (
            [_with(_without(COMPARE_ROW, "relation"), kind="ratio", tolerance={"rel": 0.1, "reason": "r"})],
            ["zz_compare", "value"],
        ),
        "claims_trend_bad_sign": ([_with(TREND_ROW, sign=2)], ["zz_trend", "sign"]),
        "claims_trend_without_coord": ([_without(TREND_ROW, "coord")], ["zz_trend", "coord"]),
        "claims_trend_bad_scale": ([_with(TREND_ROW, coord_scale="ln")], ["zz_trend", "coord_scale"]),
        "claims_duplicate_id": (
            [VALUE_ROW, _with(VALUE_ROW, variable="stick_time")],
            ["zz_value", "already used"],
        ),
    }
)

#: Rows that are well-formed alone but wrong against the config or the pinned ids (stickslip.claims
#: .check_claims, what the Snakefile calls at parse time): (rows, words).
BAD_CLAIMS_IN_CONTEXT = {
    "claims_pin_for_an_unknown_reading": (
        [_with(VALUE_ROW, expected={"default": "deviates", "consistent_captoin": "reproduced"})],
        ["zz_value", "expected.consistent_captoin", "not a reading"],
    ),
    "claims_fe_row_without_its_other_speed": (
        [_with(VALUE_ROW, dataset="results/fe/lower_face_drop/section9_kinematic_15p2rpm.nc", model="beam")],
        ["zz_value", "15p2rpm", "twin", "one_speed"],
    ),
    "claims_twin_that_does_not_exist": (
        [
            _with(
                VALUE_ROW,
                dataset="results/fe/lower_face_drop/section9_kinematic_15p2rpm.nc",
                model="beam",
                twin="zz_gone",
            )
        ],
        ["zz_value", "twin", "zz_gone"],
    ),
    "claims_twin_at_the_same_speed": (
        [
            _with(
                VALUE_ROW,
                dataset="results/fe/lower_face_drop/section9_kinematic_15p2rpm.nc",
                model="beam",
                twin="zz_b",
            ),
            _with(
                VALUE_ROW,
                id="zz_b",
                dataset="results/fe/lower_face_drop/section11_penalty_15p2rpm.nc",
                model="beam",
                twin="zz_value",
            ),
        ],
        ["zz_value", "twin", "other disc speed"],
    ),  # fmt: skip
    "claims_note_for_an_unknown_reading": (
        [_with(VALUE_ROW, note={"eq9_text": "why"})],
        ["zz_value", "note.eq9_text", "not a reading"],
    ),
    "claims_row_not_pinned": ([VALUE_ROW], ["zz_value", "not in the pinned id list"]),
}


#: Cases also run through the real pipeline: one schema error, one resolver error, one cross-section error.
END_TO_END = ("mass_negative", "ode45_negative_rtol", "missing_friction_table", "friction_table_not_a_table")


def base_config(small: bool = True) -> dict:
    """The repository's config, with the small CI config over it unless ``small`` is False."""
    files = sorted((ROOT / "config").glob("*.yaml"))
    return load_config(files + (sorted((ROOT / "config" / "test").glob("*.yaml")) if small else []))


PRODUCIBLE = ["results/onedof/friction_mu_vr.csv"]
