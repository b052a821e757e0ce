"""Transient peer: CalculiX (ccx, C3D8I strip on a translating block) vs the project's continuum strip over
the first milliseconds of a drop start, same constant mu, same penalty contact (issue 41, point 3).

Setup (both sides): the config's 100 x 1 x 1 mm steel strip, 100 x 1 elements, clamped at x = 0, gravity
from t = 0 on the undeformed strip whose free-end lower corner touches the support (drop start); penalty
contact 1000 N/mm at that corner (Section 11's stiffness); one friction coefficient mu = 0.4 (ccx has no
mu(slip rate)); support surface moving at 0.5 mm/s along +x (clockwise disc, angle 0); no material
damping (beta = 0) on either side. ccx: ``stickslip.fe.ccx_deck.ccx_scene_deck`` (implicit HHT dynamics,
automatic increments up to ``--dt``, elastic stick of slope ``--stick-slope``); continuum:
``fe.continuum`` (explicit central differences, exact stick). ccx checks contact and dynamics, not the
velocity-weakening mechanism.

Compared over the window, on ccx's increments (continuum interpolated): the contact normal force and the
tip (free-end lower corner) horizontal displacement, each as rms(ccx - continuum) / max|continuum| in %.

Tolerances: 5 % of peak for the force, 2 % for the displacement. The continuum's own refinement moves them
by 0.8 % / 0.03 % (mesh 200 x 2) and 0.06 % / 0.001 % (step dt/2) over 0.5 ms (printed on every run); the
rest of the difference is not discretisation of either side but model difference: consistent (C3D8I) vs
lumped (QM6) mass, HHT-alpha implicit vs central-difference stepping of a ringing dominated by the axial and
tip modes (whose phase error grows with time), an elastic stick spring vs exact stick, a flat block vs the
disc. The bounds are those of a previous trial (C3D20R, 5 ms: 2.4 % / 0.4 %) with a margin; measured here
(C3D8I, 0.5 ms): 4.0 % / 0.17 %.

Window: 0.5 ms by default. ccx 2.20 stalls on this deck at 0.574 ms ("too many cutbacks": its implicit
contact dynamics cuts the increment to 1e-10 s), so a 2 ms run does not finish; 0.5 ms takes ~30 s of ccx
CPU.

Usage: python benchmarks/bench_fe_transient_peer.py [--t-end 0.0005] [--dt 1e-6] [--keep DIR]
Exit status 1 when either difference exceeds its tolerance, 2 when ccx fails or is missing.
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
from pathlib import Path

import numpy as np
import yaml

from stickslip.fe.ccx_deck import ccx_scene_deck, contact_frame
from stickslip.fe.continuum import build_continuum, integrate_continuum
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable
from stickslip.validation.calculix import CalculixError, dat_time_series, run_ccx

ROOT = Path(__file__).resolve().parents[1]
MU = 0.4
PENALTY = 1000.0  # N/mm at the contact node (Section 11's)
SPEED = 0.5  # mm/s
TOL_FORCE = 5.0  # % of peak
TOL_TIP = 2.0  # % of peak


def rms_pct(a: np.ndarray, b: np.ndarray) -> float:
    """rms(a - b) / max|b| in %."""
    return float(100.0 * np.sqrt(np.mean((a - b) ** 2)) / np.max(np.abs(b)))


def continuum_run(beam: BeamParams, nx: int, ny: int, t_end: float, safety: float = 0.9):
    disc = DiscParams(surface_speed_mm_s=SPEED)
    contact = ContactParams(method="penalty", penalty_stiffness=PENALTY)
    scene = build_continuum(beam, disc, contact, FrictionTable((0.0,), (MU,)), nx=nx, ny=ny)
    return integrate_continuum(scene, t_end, safety_factor=safety, initial_state="drop")


def sampled(res, times):
    return (np.interp(times, res.t, res.normal_force), np.interp(times, res.t, res.x))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-end", type=float, default=5e-4, help="simulated window [s]")
    ap.add_argument("--dt", type=float, default=1e-6, help="ccx's largest increment [s]")
    ap.add_argument("--stick-slope", type=float, default=PENALTY, help="ccx stick slope [N/mm]")
    ap.add_argument("--keep", type=Path, default=None, help="keep ccx's files in this folder")
    args = ap.parse_args(argv)

    fe = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]
    beam = BeamParams.from_mapping(fe["defaults"]["beam"])
    mapping = {
        "beam": fe["defaults"]["beam"],
        "disc": {"surface_speed_mm_s": SPEED, "diameter": fe["defaults"]["disc"]["diameter"]},
        "contact": {"method": "penalty", "penalty_stiffness": PENALTY},
    }
    deck = ccx_scene_deck(
        "transient_peer", mapping, 100, 1, t_end=args.t_end, dt=args.dt, mu=MU, stick_slope=args.stick_slope
    )
    w0 = time.perf_counter()
    try:
        dat = run_ccx(deck, "transient_peer", workdir=args.keep, timeout=7200.0)
    except CalculixError as err:
        print(f"ccx failed: {err}", file=sys.stderr)
        return 2
    wall = time.perf_counter() - w0
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_children = usage.ru_utime + usage.ru_stime
    series = dat_time_series(dat)
    times, tip = series[("displacements", "TIPLOW")]
    _, rf = series[("total force", "BLOCKN")]
    _, n, t = contact_frame(beam, ContactParams(), "clockwise")
    ccx_normal = rf[:, :2] @ n  # the block's reaction is the contact force on the strip
    ccx_friction = rf[:, :2] @ t
    keep = times > 0
    times, ccx_normal, ccx_friction, ccx_x = times[keep], ccx_normal[keep], ccx_friction[keep], tip[keep, 0]

    c0 = time.process_time()
    ref = continuum_run(beam, 100, 1, args.t_end)
    fine = continuum_run(beam, 200, 2, args.t_end)
    half = continuum_run(beam, 100, 1, args.t_end, safety=0.45)
    c_cpu = time.process_time() - c0
    n_ref, x_ref = sampled(ref, times)
    f_ref = np.interp(times, ref.t, ref.friction_force)
    d_force, d_tip = rms_pct(ccx_normal, n_ref), rms_pct(ccx_x, x_ref)
    d_fric = rms_pct(ccx_friction, f_ref)
    refinement = {
        name: (rms_pct(sampled(r, times)[0], n_ref), rms_pct(sampled(r, times)[1], x_ref))
        for name, r in (("mesh 200x2", fine), ("step dt/2", half))
    }

    print(
        f"window {args.t_end:g} s, ccx increments printed {times.size}, ccx largest increment {args.dt:g} s"
    )
    print(f"ccx: wall {wall:.1f} s, CPU {cpu_children:.1f} s; continuum (3 runs): CPU {c_cpu:.1f} s")
    peaks = np.max(np.abs(n_ref)), np.max(np.abs(x_ref))
    print(f"peak continuum normal force {peaks[0]:.4e} N, peak tip x {peaks[1]:.4e} mm")
    for name, (a, b) in refinement.items():
        print(f"continuum refinement {name}: normal force {a:.3f} %, tip x {b:.3f} % (of peak, rms)")
    print(f"friction force (along the support velocity) difference {d_fric:.3f} % (reported, no tolerance)")
    ok_force, ok_tip = d_force <= TOL_FORCE, d_tip <= TOL_TIP
    print(
        f"contact normal force: rms difference {d_force:.3f} % of peak, tolerance {TOL_FORCE:g} %: "
        f"{'ok' if ok_force else 'EXCEEDED'}"
    )
    print(
        f"tip horizontal displacement: rms difference {d_tip:.3f} % of peak, tolerance {TOL_TIP:g} %: "
        f"{'ok' if ok_tip else 'EXCEEDED'}"
    )
    return 0 if ok_force and ok_tip else 1


if __name__ == "__main__":
    sys.exit(main())
