"""Where the compiled exact solver and its pure-Python reference part: random sweeps beyond the property test.

``tests/solvers/test_exact_compiled.py`` runs 60 fixed examples of its parameter range; this script draws
many more and prints every run on which the two disagree under that test's own tolerances (``assert_agree``,
``term_scales``), with its parameters to the last bit, so that each can be rerun alone. Two draws:

* ``uniform``: the test's range, si reading, belt decelerating at 0.2 mm/s^2 (where a stop meets the plateau);
* ``ends``: each parameter at an end of its range 30 % of the time (what a property-based search tries).

    PYTHONPATH=src .venv/bin/python benchmarks/sweep_exact_agreement.py ends --seed 11 --runs 1000

Prints one JSON line per disagreement, then ``runs, disagreements``. Slow on purpose (two solvers, 10 s
runs): ~1000 runs a minute on one core.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "tests" / "solvers")]

from test_exact_compiled import assert_agree, solve_both, term_scales  # noqa: E402

from stickslip.model import BeltModel  # noqa: E402
from stickslip.model.params import BeltParams  # noqa: E402
from stickslip.solvers import CompiledExactSolver  # noqa: E402
from stickslip.solvers.exact_compiled import python_reference  # noqa: E402

#: the property test's range (params_strategy)
RANGES = dict(mass=(0.1, 10), stiffness=(0.5, 50), damping=(0, 5), sigma=(0, 1), mu_s=(0.05, 1.5),
              normal_force=(1, 100), belt_velocity=(0.05, 2), x0=(-1, 1), v0=(-1, 1.5))  # fmt: skip


def draw(rng, mode: str) -> tuple[dict, str]:
    def value(lo, hi):
        r = rng.random() if mode == "ends" else 1.0
        return float(lo) if r < 0.15 else float(hi) if r < 0.3 else float(rng.uniform(lo, hi))

    changes = {key: value(*bounds) for key, bounds in RANGES.items()}
    uniform = mode == "uniform"
    changes.update(
        belt_deceleration=0.2 if uniform else float(rng.choice([0.0, 0.025, 0.2])),
        plateau_speed=float(rng.choice([np.inf, 0.6, 2.0])),
        units="si" if uniform else str(rng.choice(["as_given", "si"])),
    )
    return changes, str(rng.choice(["consistent", "eq3_printed", "eq4_printed"]))


def disagreement(changes: dict, variant: str) -> str | None:
    """Why the two solvers disagree on this run (None: they agree, or both refuse it alike)."""
    model = BeltModel.build(BeltParams(**changes), variant)
    t_eval = np.linspace(0.0, 10.0, 501)
    try:
        ref, got = solve_both(CompiledExactSolver(), model, 10.0, t_eval)
    except ValueError:  # the reference refused (overflow): the kernel must refuse alike
        try:
            with np.errstate(all="ignore"):
                CompiledExactSolver().solve(model, 10.0, t_eval)
        except ValueError:
            return None
        return "the reference refused the run, the kernel ran it"
    except Exception as exc:  # noqa: BLE001 (any other error is a finding)
        return f"{type(exc).__name__}: {exc}"
    terms = (0.0, 0.0, 1.0)
    if ref.ok:
        with np.errstate(all="ignore"):
            terms = term_scales(python_reference(CompiledExactSolver()).segments(model, 10.0))
    try:
        assert_agree(ref, got, strict=False, terms=terms)
    except AssertionError as exc:
        return f"{len(ref.segments)} vs {len(got.segments)} segments: " + " ".join(str(exc).split())[:300]
    return None


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("uniform", "ends"))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--runs", type=int, default=1000)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    found = runs = 0
    for _ in range(args.runs):
        changes, variant = draw(rng, args.mode)
        try:
            BeltParams(**changes)
        except ValueError:
            continue  # outside the model's own checks: not a run
        runs += 1
        why = disagreement(changes, variant)
        if why is not None:
            found += 1
            print(json.dumps({"changes": changes, "variant": variant, "why": why}), flush=True)
    print(f"{runs} runs, {found} disagreements")
    return 0


if __name__ == "__main__":
    sys.exit(main())
