"""What the beam-on-disc model's outputs mean: the model interpretation every FE dataset records, and the
units and long names of its scalar metrics (stickslip.fe.metrics, .modes, .run compute them)."""

from __future__ import annotations

INTERPRETATION = (
    "2-D frame elements (axial bar + Euler-Bernoulli bending stiffness, Rayleigh rotary inertia rho*I), "
    "clamped "
    "left end, steel E=210 GPa rho=7850 kg/m3, 1 mm out-of-plane width (gravity-only normal load: contact "
    "pressure, frequencies and displacements independent of width, forces proportional to it); rigid disc, "
    "small-displacement contact at the free end on the lower face (h/2 below the axis, the paper's slave "
    "surface) or on the axis (reading), fixed normal/tangent; contact angle = tilt of the disc normal at the "
    "contact towards the clamp; mu(|v_r|) from the tabulated friction law with static limit mu(0) and exact "
    "stick; light stiffness-proportional damping beta (solver.stiffness_damping) so that the response "
    "converges in mesh and step; start from rest undeformed with gravity at t=0 (drop, as ABAQUS/Explicit) "
    "or from the gravity equilibrium in contact (static), per reading; node 1 = the free-end point named by "
    "contact.output_node; displacements from the initial position."
)

#: the response quantities the convergence study follows and the model comparison compares
RESPONSE_QUANTITIES = (
    "horizontal_amplitude",
    "mean_horizontal_displacement",
    "dominant_frequency",
    "stick_fraction",
    "separation_fraction",
)

#: scalar metric name -> (UDUNITS units, long name)
UNITS = {
    "max_horizontal_displacement": ("mm", "maximum horizontal displacement of node 1"),
    "min_horizontal_displacement": ("mm", "minimum horizontal displacement of node 1"),
    "max_abs_horizontal_displacement": ("mm", "largest absolute horizontal displacement of node 1"),
    "mean_horizontal_displacement": ("mm", "mean horizontal displacement of node 1 (second half)"),
    "abs_mean_horizontal_displacement": ("mm", "absolute mean horizontal displacement (second half)"),
    "horizontal_amplitude": ("mm", "half peak-to-peak horizontal displacement (second half)"),
    "max_vertical_displacement": ("mm", "maximum absolute vertical displacement of node 1"),
    "vertical_amplitude": ("mm", "half peak-to-peak vertical displacement (second half)"),
    "max_abs_horizontal_velocity": ("mm s-1", "maximum absolute horizontal velocity of node 1"),
    "max_abs_vertical_velocity": ("mm s-1", "maximum absolute vertical velocity of node 1"),
    "midspan_vertical_amplitude": ("mm", "half peak-to-peak vertical displacement of the mid-span node"),
    "midspan_max_abs_vertical_velocity": (
        "mm s-1",
        "maximum absolute vertical velocity of the mid-span node",
    ),
    "dominant_frequency": ("Hz", "dominant frequency of the horizontal displacement"),
    "vertical_dominant_frequency": ("Hz", "dominant frequency of the vertical displacement"),
    "stick_fraction": ("1", "fraction of increments in stick (second half of the run)"),
    "slip_fraction": ("1", "fraction of increments in slip (second half of the run)"),
    "separation_fraction": ("1", "fraction of increments separated (second half of the run)"),
    "stick_fraction_whole_run": ("1", "fraction of increments in stick (whole run)"),
    "separation_fraction_whole_run": ("1", "fraction of increments separated (whole run)"),
    "static_normal_force": ("N", "static contact normal force (gravity only)"),
    "max_normal_force_ratio": ("1", "maximum normal force over static normal force"),
    "stable_time_step": ("s", "central-difference stability limit 2/omega_max"),
    "time_step": ("s", "time step used"),
    "increment_count": ("1", "number of increments"),
    "increment_count_0p65s": ("1", "number of increments to reach 0.65 s"),
    "cpu_time": ("s", "CPU time of the time loop"),
    "stick_end_time": ("s", "time of the last stick sample"),
    "first_stick_duration": ("s", "duration of the initial stick phase"),
    "horizontal_vertical_correlation": ("1", "correlation of horizontal and vertical displacement"),
    "separation_burst_time": (
        "s",
        "start of the first separation burst (first 5 ms window separated >= half the run's largest share)",
    ),
    "horizontal_amplitude_growth_ratio": ("1", "last-window over second-window horizontal half peak-to-peak"),
    "horizontal_nearest_mode_ratio": ("1", "horizontal dominant frequency over nearest natural frequency"),
    "vertical_nearest_mode_ratio": ("1", "vertical dominant frequency over nearest natural frequency"),
    "disc_surface_speed": ("mm s-1", "disc surface speed at the contact"),
    "first_mode_growth_rate": (
        "s-1",
        "growth rate of the first contact-held mode's horizontal amplitude at node 1 (leading segment)",
    ),
    "first_mode_growth_end": ("s", "end of the leading segment the first-mode growth rate is fitted over"),
    "first_mode_growth_rate_linear": (
        "s-1",
        "linearised sliding system's growth rate of the first contact-held mode (eigen-analysis, mu'(V))",
    ),
    "first_mode_frequency": ("Hz", "first natural frequency with contact held"),
    "horizontal_velocity_trend": ("1", "sign of the trend of the horizontal velocity envelope"),
    "vertical_velocity_trend": ("1", "sign of the trend of the vertical velocity envelope"),
    "horizontal_displacement_trend": ("1", "sign of the trend of the horizontal displacement envelope"),
}


def metric_attrs(name: str, long_name: str | None = None) -> dict:
    """CF attributes of a scalar metric; one missing from UNITS is dimensionless, named ``long_name``
    (default: the name itself)."""
    units, text = UNITS.get(name, ("1", name if long_name is None else long_name))
    return {"units": units, "long_name": text}


def cf_attrs(title: str, **attrs) -> dict:
    """A dataset's own attributes: CF conventions, its ``title``, then ``attrs`` in the order given."""
    return {"Conventions": "CF-1.10", "title": title, **attrs}
