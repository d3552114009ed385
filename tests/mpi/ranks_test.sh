#!/bin/bash
# `mpirun -np 2` and `-np 3 --oversubscribe` sweeps write the same bytes as one process, for a
# frequency-domain and a time-domain study; a run that throws on some rank is reported with
# its rank and run, exit 1; a rank that dies ends the job. Nothing may hang: every mpirun has a
# timeout. Skipped (exit 77) in a build without MPI.
# usage: ranks_test.sh RIDEFIT SOURCE_DIR MPI(ON|OFF) MPIEXEC
set -uo pipefail
. "$(dirname "$0")/mpi_test_common.sh" ranks_test "$@"

cat >"$tmp/frequency.yaml" <<YAML
model: $src/datasets/vehicles/ajayi_half_car.yaml
roads:
  smooth: $src/datasets/excitations/smooth_road_seed001.yaml
  gravel: $src/datasets/excitations/gravel_road_seed001.yaml
speeds_km_per_h: [20, 60]
vary:
  - parameter: [front.damping_Ns_per_m, rear.damping_Ns_per_m]
    range: {from: 500, to: 4000, count: 9, spacing: linear}
YAML
cat >"$tmp/time.yaml" <<YAML
model: $src/datasets/vehicles/ajayi_half_car.yaml
roads:
  gravel: $src/datasets/excitations/gravel_road_seed001.yaml
speeds_km_per_h: [40]
method: time
time: {output_rate_Hz: 500, settle_s: 1, duration_s: 4}
vary:
  - parameter: [front.damping_Ns_per_m, rear.damping_Ns_per_m]
    values: [800, 1500, 3000]
YAML

for study in frequency time; do
  "$ridefit" sweep "$tmp/$study.yaml" -o "$tmp/$study.1.csv" >/dev/null ||
    fail "$study: the one-process sweep failed"
  ranks 2 "$ridefit" sweep "$tmp/$study.yaml" -o "$tmp/$study.2.csv" >/dev/null ||
    fail "$study: mpirun -np 2 failed"
  ranks 3 --oversubscribe "$ridefit" sweep "$tmp/$study.yaml" --threads 1 \
    -o "$tmp/$study.3.csv" >/dev/null ||
    fail "$study: mpirun -np 3 --oversubscribe failed"
  cmp "$tmp/$study.1.csv" "$tmp/$study.2.csv" || fail "$study: 2 ranks wrote other bytes"
  cmp "$tmp/$study.1.csv" "$tmp/$study.3.csv" || fail "$study: 3 ranks wrote other bytes"
  [ "$(wc -l <"$tmp/$study.1.csv")" -gt 3 ] || fail "$study: the sweep wrote no rows"
done

# --json under ranks says how the work was shared: 36 runs, rank 0's share and 144 bytes a run
# gathered (17 doubles and a length) plus 16 a request.
ranks 2 "$ridefit" sweep "$tmp/frequency.yaml" --threads 1 --json >"$tmp/ranks.json" ||
  fail "--json under 2 ranks failed"
grep -q '"count": 2' "$tmp/ranks.json" || fail "--json under 2 ranks: no rank count"
python3 - "$tmp/ranks.json" <<'PY' || fail "--json under 2 ranks: the counts do not add up"
import json, sys
r = json.load(open(sys.argv[1]))["ranks"]
other = 36 - r["runs_on_rank0"]
assert 0 <= other <= 36, r
# One worker: a first request, then one per chunk, each 16 bytes; 144 bytes per run gathered.
assert r["bytes_received_by_rank0"] == 16 * (r["chunks_to_other_ranks"] + 1) + 144 * other, r
PY

# A run that throws (run 6 of 36, 1-based) on whichever rank took it.
RIDEFIT_TEST_FAULT=throw:5 ranks 2 "$ridefit" sweep "$tmp/frequency.yaml" --threads 1 \
  -o "$tmp/fault.csv" >"$tmp/fault.out" 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "a throwing run: exit $code (124: it hung)"
grep -q "run 6: injected failure" "$tmp/fault.out" || {
  cat "$tmp/fault.out" >&2
  fail "a throwing run: the message does not name run 6"
}
grep -q "rank [0-9]" "$tmp/fault.out" || fail "a throwing run: the message names no rank"
[ ! -e "$tmp/fault.csv" ] || fail "a throwing run left a results file"

# A rank that dies on run 6: the job ends, not hangs.
RIDEFIT_TEST_FAULT=die:5 ranks 2 "$ridefit" sweep "$tmp/frequency.yaml" --threads 1 \
  -o "$tmp/died.csv" >"$tmp/died.out" 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "a dying rank: exit $code (124: it hung)"
[ ! -e "$tmp/died.csv" ] || fail "a dying rank left a results file"

# Bad input under mpirun: exit 2 from every rank, one message.
ranks 2 "$ridefit" sweep "$tmp/missing.yaml" >"$tmp/bad.out" 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "bad input: exit $code"
echo "ranks_test: sweeps over 2 and 3 ranks identical to one process; faults reported"
