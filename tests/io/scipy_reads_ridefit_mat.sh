#!/bin/bash
# scipy.io.loadmat reads `ridefit simulate -o run.mat` to the values and units of the same run's
# CSV (an independent check of matio's writer). usage: scipy_reads_ridefit_mat.sh RIDEFIT SRC
set -euo pipefail
ridefit=$1
src=$2
python=/usr/bin/python3
if ! [ -x "$python" ] || ! "$python" -c 'import scipy.io, numpy' 2>/dev/null; then
  echo "skipped: /usr/bin/python3 with scipy (Debian: python3-scipy) is not installed"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf 'type: log_sweep\ninitial_amplitude_m: 0.002\nduration_s: 3\n' >"$tmp/sweep.yaml"
for out in run.csv run.mat; do
  "$ridefit" simulate "$src/datasets/vehicles/passat_b8_front.yaml" "$tmp/sweep.yaml" \
    -o "$tmp/$out" >/dev/null
done
"$python" - "$tmp/run.csv" "$tmp/run.mat" <<'PY'
import re, sys
import numpy as np
import scipy.io
csv_path, mat_path = sys.argv[1:]
header = open(csv_path).readline().strip().split(",")
columns = [re.fullmatch(r"(\w+)\[(.+)\]", h).groups() for h in header]
table = np.loadtxt(csv_path, delimiter=",", skiprows=1)
mat = scipy.io.loadmat(mat_path)
names = [k for k in mat if not k.startswith("__") and k != "units"]
assert names == [n for n, _ in columns], (names, columns)
units = mat["units"][0, 0]
for c, (name, unit) in enumerate(columns):
    values = mat[name]
    assert values.shape == (table.shape[0], 1), (name, values.shape)
    assert str(units[name][0]) == unit, (name, units[name], unit)
    # The CSV holds each double's shortest exact text: equal bit for bit.
    assert np.array_equal(values[:, 0], table[:, c]), (name, np.max(np.abs(values[:, 0] - table[:, c])))
print(f"scipy read {len(columns)} channels x {table.shape[0]} samples equal to the CSV")
PY
