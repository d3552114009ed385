#!/usr/bin/env python3
"""Fits Dahl friction to a strut rig test with the Python module and plots the loop.

    PYTHONPATH=build/python python3 examples/python/fit_loop.py \
        datasets/vehicles/passat_b8_front.yaml datasets/lab/triangle_3mm_1mmps.csv [loop.png]

Loads the shipped rig record (a slow 3 mm triangle at 1 mm/s), fits σ0, Fc, the Dahl exponent
and the load cell's offset from the model file's start values (as `ridefit fit hysteresis
--interpolation linear`), prints the parameters with their standard errors, and draws measured and fitted force
over displacement with matplotlib when it is installed. Exit code 1 when the fit does not
explain the data or a value is not finite.
"""

import math
import sys

import ridefit


def main(model_file: str, record_file: str, figure_file: str = "fit_loop.png") -> int:
    record = ridefit.load_hysteresis_record(record_file)
    free = ["dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent", "force_offset_N"]
    # A triangle is piecewise linear between samples.
    fit = ridefit.fit_hysteresis(record, model_file, free=free, interpolation="linear")
    for p in fit["parameters"]:
        error = p["standard_error"]  # None when the data cannot determine it
        print(f"{p['name']:<24} {p['value']:12.6g} ± {'-' if error is None else f'{error:.3g}'}")
    print(f"force NRMSE {fit['nrmse_percent']:.2f} %, {fit['iterations']} iterations")
    finite = all(math.isfinite(p["value"]) for p in fit["parameters"])
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: skipped the plot")
    else:
        figure, axes = plt.subplots()
        axes.plot(1e3 * record["displacement_m"], record["force_N"], label="measured")
        axes.plot(1e3 * record["displacement_m"], fit["fitted_force_N"][0], label="fitted")
        axes.set_xlabel("displacement [mm]")
        axes.set_ylabel("force [N]")
        axes.legend()
        figure.savefig(figure_file, dpi=100)
        print(f"Figure: {figure_file}")
    return 0 if finite and fit["explains_data"] else 1


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
