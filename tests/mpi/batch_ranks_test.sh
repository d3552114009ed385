#!/bin/bash
# `mpirun -np 2` and `-np 3 --oversubscribe` batches write the same files as one process (every
# byte, the summaries' wall times aside), with a garbage record reported as a failed job while
# the others complete (exit 1); a job that throws inside the task farm ends the run with the
# summary so far; a rank that dies ends the job, and the summary so far stays. Nothing may
# hang: every mpirun has a timeout. Skipped (exit 77) in a build without MPI.
# usage: batch_ranks_test.sh RIDEFIT SOURCE_DIR MPI(ON|OFF) MPIEXEC
set -uo pipefail
. "$(dirname "$0")/mpi_test_common.sh" batch_ranks_test "$@"

# The files of an output folder without the summaries' wall times, for comparison.
without_times() {
  local dir=$1
  sed -E 's/^(([^,]*,){11})[^,]*,/\1,/' "$dir/summary.csv" >"$dir.csv.cmp"
  grep -v '"wall_time_s"' "$dir/summary.json" >"$dir.json.cmp"
}

# Three shim rig tests (a glob), a garbage record, a PSD fit and a rig diagnosis: shipped data.
mkdir -p "$tmp/lab"
cp "$src"/datasets/lab/shim_*.csv "$tmp/lab/"
printf 'time[s],displacement[mm],force[N]\n0,1,2\nnot,a,number\n' >"$tmp/lab/zz_garbage.csv"
cat >"$tmp/jobs.yaml" <<YAML
defaults:
  command: fit hysteresis
  model: $src/datasets/vehicles/passat_b8_front.yaml
  options: {free: [dahl_sigma0_N_per_m, coulomb_force_N, force_offset_N], interpolation: linear}
jobs:
  - records: lab/*.csv
  - record: $src/datasets/hidden/baseline_only.csv
    name: psd
    command: fit psd
    model: $src/datasets/hidden/baselines/passat_slip.yaml
    options: {free: damping_Ns_per_m, interpolation: false}
  - record: lab/shim_2mm.csv
    name: loops
    command: diagnose
    options: {interpolation: false, effects: gas_force,
              free: [damping_Ns_per_m, force_offset_N, coulomb_force_N]}
YAML
cd "$tmp" || fail "no temporary folder"

"$ridefit" batch jobs.yaml -o one -q >one.out 2>&1
code=$?
[ "$code" -eq 1 ] || { cat one.out >&2; fail "one process: exit $code, expected 1 (a failed job)"; }
ranks 2 "$ridefit" batch jobs.yaml -o two -q >two.out 2>&1
code=$?
[ "$code" -eq 1 ] || { cat two.out >&2; fail "mpirun -np 2: exit $code, expected 1"; }
ranks 3 --oversubscribe "$ridefit" batch jobs.yaml -o three -q --threads 1 >three.out 2>&1
code=$?
[ "$code" -eq 1 ] || { cat three.out >&2; fail "mpirun -np 3: exit $code, expected 1"; }

grep -q '^4,zz_garbage,fit hysteresis,lab/zz_garbage.csv,failed,' one/summary.csv ||
  fail "the garbage record is not a failed row: $(cat one/summary.csv)"
[ "$(grep -c ',ok,' one/summary.csv)" -eq 5 ] || fail "not 5 jobs ok: $(cat one/summary.csv)"
for dir in one two three; do without_times "$dir"; done
for n in two three; do
  diff -r -x summary.csv -x summary.json one "$n" >/dev/null ||
    fail "$n ranks: the job folders differ from one process'"
  cmp one.csv.cmp "$n.csv.cmp" || fail "$n ranks: summary.csv differs (wall times aside)"
  cmp one.json.cmp "$n.json.cmp" || fail "$n ranks: summary.json differs (wall times aside)"
done
# --json under ranks: the summary plus how the jobs were shared (every job once; the results,
# files and summary rows, came back to rank 0 as bytes).
ranks 2 "$ridefit" batch jobs.yaml -o json --json --threads 1 >json.out 2>json.err
/usr/bin/env python3 - json.out <<'PY' || fail "mpirun -np 2 --json: no ranks block that adds up"
import json, sys
j = json.load(open(sys.argv[1]))
r = j["ranks"]
assert r["count"] == 2, r
assert r["jobs_on_rank0"] + r["jobs_to_other_ranks"] == 6, r
assert r["jobs_to_other_ranks"] == 0 or r["bytes_received_by_rank0"] > 1000, r
assert r["bytes_sent_by_rank0"] > 0, r
assert len(j["jobs"]) == 6
PY
for job in shim_0mm shim_2mm shim_4mm psd; do
  [ -s "one/$job/model.yaml" ] && [ -s "one/$job/result.json" ] || fail "$job: no model or result"
done
[ -s one/loops/report.md ] || fail "the diagnosis wrote no report"

# A job that throws inside the task farm (task 2, the third job): the run ends with exit 1,
# naming it; the summary so far stays, the jobs not done are `not run`.
RIDEFIT_TEST_FAULT=throw:2 ranks 2 "$ridefit" batch jobs.yaml -o thrown -q --threads 1 \
  >thrown.out 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "a throwing job: exit $code (124: it hung)"
grep -q "run 3: injected failure" thrown.out || {
  cat thrown.out >&2
  fail "a throwing job: the message does not name it"
}
grep -q ',not run,' thrown/summary.csv || fail "a throwing job: no job is marked not run"

# A rank that dies on task 3: the job ends (no hang); the summary so far stays.
RIDEFIT_TEST_FAULT=die:3 ranks 2 "$ridefit" batch jobs.yaml -o died -q --threads 1 \
  >died.out 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "a dying rank: exit $code (124: it hung)"
[ -s died/summary.csv ] && [ -s died/summary.json ] || fail "a dying rank: no summary so far"
[ "$(wc -l <died/summary.csv)" -eq 7 ] || fail "a dying rank: the summary lacks rows"

# A bad job file under mpirun: exit 2 from every rank, nothing written.
printf 'jobs:\n  - record: lab/missing.csv\n' >bad.yaml
ranks 2 "$ridefit" batch bad.yaml -o bad >bad.out 2>&1
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "bad job file: exit $code"
grep -q "bad.yaml: job 1 (missing): key 'record'" bad.out || {
  cat bad.out >&2
  fail "bad job file: the message does not name the job and key"
}
[ ! -e bad ] || fail "bad job file: an output folder was made"
echo "batch_ranks_test: batches over 2 and 3 ranks identical to one process; faults reported"
