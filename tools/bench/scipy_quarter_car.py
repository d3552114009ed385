#!/usr/bin/python3
"""Whole-process comparison: `ridefit simulate` against what a Python user writes in a few lines.

Runs `ridefit simulate MODEL EXCITATION` (the default ESDIRK at rtol 1e-6, as scipy below) as a
process and times it; then, in this process, integrates the same stick/slip quarter car (seed
000, Equations 9–11, Dahl friction) with scipy's solve_ivp (LSODA, rtol 1e-6, the same per-state
absolute tolerances) over the road ridefit wrote (its `road[m]` channel through a cubic spline).
Python's time is its own: the interpreter's start and imports plus the model and the integration,
not ridefit's run or the parse of the CSV that hands the road over. Prints both wall times, their
ratio and the body-acceleration RMS of each. Needs numpy, scipy and PyYAML (Debian: python3-scipy python3-yaml); not part of the tests.

  tools/bench/scipy_quarter_car.py build/tools/ridefit \
      datasets/vehicles/passat_b8_front.yaml datasets/excitations/iso8608_class_a_50kmh.yaml
"""
import time

START = time.perf_counter()

import csv  # noqa: E402
import math  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402

import numpy as np  # noqa: E402
import yaml  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.interpolate import CubicSpline  # noqa: E402

IMPORTS_DONE = time.perf_counter()


def _is_number(value):
    try:
        float(value)
        return True
    except ValueError:
        return False


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    ridefit, model_file, excitation_file = sys.argv[1:]
    with tempfile.TemporaryDirectory() as tmp:
        out = f"{tmp}/ridefit.csv"
        t0 = time.perf_counter()
        subprocess.run([ridefit, "simulate", model_file, excitation_file, "-o", out,
                        "--damper-state", "stick_slip", "--rtol", "1e-6"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        ridefit_wall = time.perf_counter() - t0
        with open(out) as f:
            rows = list(csv.DictReader(f))
    t = np.array([float(r["time[s]"]) for r in rows])
    road = np.array([float(r["road[m]"]) for r in rows])
    body_ridefit = np.array([float(r["body_acc[m/s^2]"]) for r in rows])

    python_start = time.perf_counter()
    with open(model_file) as f:
        # PyYAML reads 5.0e6 (no exponent sign) as a string: take every number as a float.
        p = {k: float(v) for k, v in yaml.safe_load(f).items()
             if isinstance(v, (int, float, str)) and _is_number(v)}
    ms, mu = p["sprung_mass_kg"], p["unsprung_mass_kg"]
    kt, ct = p["tyre_stiffness_N_per_m"], p["tyre_damping_Ns_per_m"]
    k_sp = 1.0 / (1.0 / p["spring_stiffness_N_per_m"] +
                  1.0 / p["top_mount_spring_path_stiffness_N_per_m"])
    k_tm, c = p["top_mount_stiffness_N_per_m"], p["damping_Ns_per_m"]
    s0, fc, d = p["dahl_sigma0_N_per_m"], p["coulomb_force_N"], p["dahl_exponent"]
    h = CubicSpline(t, road)
    dh = h.derivative()

    def rhs(time_s, x):
        zs, zu, vs, vu, zc, ff = x
        travel = zs - zu
        path = k_tm * (travel - zc)
        v = (path - ff) / c
        sgn = 1.0 if v >= 0 else -1.0
        s = 1.0 - ff / fc * sgn
        ffdot = s0 * v * math.copysign(abs(s) ** d, s)
        tyre = kt * (zu - h(time_s)) + ct * (vu - dh(time_s))
        return [vs, vu, -(k_sp * travel + path) / ms, (k_sp * travel + path - tyre) / mu, v, ffdot]

    rtol = 1e-6
    atol = [rtol * m for m in (1e-3, 1e-3, 1e-2, 1e-2, 1e-4, max(1.0, fc))]
    solution = solve_ivp(rhs, (t[0], t[-1]), [0.0] * 6, method="LSODA", t_eval=t, rtol=rtol,
                         atol=atol)
    body = [rhs(ti, xi)[2] for ti, xi in zip(solution.t, solution.y.T)]
    end = time.perf_counter()
    # Python's own process: the interpreter's start and imports, then the model's parameters and
    # the integration. ridefit's run and the parse of its CSV (which only hands the road over)
    # happen between the two and are not charged to it.
    python_wall = (IMPORTS_DONE - START) + (end - python_start)
    print(f"ridefit simulate (whole process): {ridefit_wall:.3f} s, body RMS "
          f"{np.sqrt(np.mean(body_ridefit ** 2)):.6f} m/s^2")
    print(f"scipy solve_ivp LSODA (whole process): {python_wall:.3f} s "
          f"(integration {end - python_start:.3f} s, {solution.nfev} RHS evaluations), body RMS "
          f"{np.sqrt(np.mean(np.square(body))):.6f} m/s^2")
    print(f"ratio: {python_wall / ridefit_wall:.1f}")


if __name__ == "__main__":
    main()
