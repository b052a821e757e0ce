"""The claims table: every number and directional statement of the paper, checked against the datasets.

A claim row (``config/claims/*.yaml``) names a dataset and a scalar variable in it. ``{reading}`` in a
dataset path makes the claim be checked once per reading of the paper's equations. Kinds:

``value``    measured variable vs the reported number within a tolerance
``ratio``    lhs / rhs vs the reported number within a tolerance
``compare``  lhs <relation> rhs
``trend``    sign of the least-squares slope of ``variable`` along ``coord`` of a sweep dataset; ``sign: 0``
             claims "no effect"; ``coord_scale: log`` fits against log10(coord). A change below
             ``min_relative_change`` (default TREND_FLOOR) is no trend.

Status is ``reproduced``, ``deviates``, ``indistinguishable`` or ``not-comparable`` (nothing measurable,
or the paper contradicts itself: rows with ``comparable: false``). Every claim reduces to a *decision
variable* on one side of a threshold (value/ratio: |measured - reported| against the tolerance band;
compare: lhs - rhs against 0; trend: the relative change against +-floor). ``margin`` is its distance to the
threshold, ``spread`` its range across the dataset's perturbation ensemble (``<variable>_ensemble``,
stickslip.ensemble). One rule for every kind, at every disc speed and in every reading: a margin below
MARGIN_FACTOR spreads is ``indistinguishable`` (the spread includes the dt/2 run). Unanimity of the members
alone is not enough: with a handful of members it would decide ties such as 0.75 > 0.75 in a reading whose
end state is set by round-off. A value the step-halving check withheld still decides a comparison through
its two steps' values (its side, when both lie beyond 3 spreads of it). ``expected`` pins the
status (one string, or one per reading); the check fails when a measured status differs from the pinned
one, so every change is deliberate.
"""
