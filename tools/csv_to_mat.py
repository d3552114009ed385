#!/usr/bin/python3
"""Converts a ridefit CSV (header `name[unit],...`) to a MATLAB v5 .mat file with scipy:
one column vector per column, in the CSV's own units, and a `units` struct naming them, which
is how ridefit reads a .mat measurement (src/ridefit/io/mat_file.h).

    /usr/bin/python3 tools/csv_to_mat.py IN.csv OUT.mat

Needs NumPy and SciPy (Debian: python3-scipy). An independent writer: it does not use matio.
"""
import re
import sys

import numpy as np
import scipy.io


def main(csv_path, mat_path):
    with open(csv_path, encoding="utf-8-sig") as f:
        header = f.readline().strip().split(",")
    names, units = [], {}
    for cell in header:
        m = re.fullmatch(r"\s*(\w+)\s*\[([^\]]+)\]\s*", cell)
        if not m:
            sys.exit(f"{csv_path}: header cell '{cell}' must read name[unit]")
        names.append(m.group(1))
        units[m.group(1)] = m.group(2).strip()
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1, ndmin=2)
    variables = {name: data[:, c] for c, name in enumerate(names)}
    variables["units"] = units
    scipy.io.savemat(mat_path, variables, format="5", do_compression=True, oned_as="column")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
