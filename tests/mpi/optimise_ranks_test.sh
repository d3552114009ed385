#!/bin/bash
# `mpirun -np 2` and `-np 3 --oversubscribe` damper tunings (starts, friction-blind optimum and
# trade-off points spread over the ranks) write the same result, model and trade-off as one
# process; a run ended midway (SIGTERM, as a batch system's time limit sends) or by a throwing
# search resumes from its journal under another number of ranks to the same optimum; a dying
# rank ends the job. Every mpirun has a timeout. Skipped (exit 77) in a build without MPI.
# usage: optimise_ranks_test.sh RIDEFIT SOURCE_DIR MPI(ON|OFF) MPIEXEC
set -uo pipefail
rank_timeout=300
. "$(dirname "$0")/mpi_test_common.sh" optimise_ranks_test "$@"

# The result without what may differ: the wall time, and (after a resume) how many
# evaluations came from the journal.
result_of() { grep -v -e '^wall_time_s:' -e '_evaluations:' "$1"; }
same_result() {  # same_result DIR REFERENCE_DIR WHAT
  [ -s "$2/r.yaml" ] && [ -s "$1/r.yaml" ] || fail "$3: no result written"
  cmp <(result_of "$2/r.yaml") <(result_of "$1/r.yaml") ||
    fail "$3: another result than one process"
  for f in r_model.yaml r_tradeoff.csv; do
    cmp "$2/$f" "$1/$f" || fail "$3: $f differs from one process"
  done
}

d=$src/datasets
cat >"$tmp/study.yaml" <<YAML
model: $d/vehicles/passat_b8_front.yaml
design:
  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000, scale: log}
  - {parameter: top_mount_stiffness_N_per_m, lower: 150000, upper: 1500000, scale: log}
load_cases:
  - {name: a50, road: $d/excitations/iso8608_class_a_50kmh.yaml, weight: 2}
  - {name: a100, road: $d/excitations/iso8608_class_a_50kmh.yaml, speed_km_per_h: 100}
  - {name: gravel, road: $d/excitations/gravel_road_seed001.yaml, speed_km_per_h: 30}
objective: {metric: body_acc_wk_rms_m_per_s2}
constraints: [{metric: dynamic_load_ratio, max: 0.2}]
optimiser: {starts: 4, max_evaluations: 40}
evaluation: {method: time, duration_s: 4, settle_s: 1, output_rate_Hz: 500}
tradeoff: {metric: dynamic_load_ratio, limits: [0.2, 0.25, 0.3]}
YAML
study=$tmp/study.yaml
run_in() {  # run_in DIR [mpirun -np N …] -- the optimise run in DIR, writing r.yaml there
  local dir=$1
  shift
  mkdir -p "$dir" && (cd "$dir" && "$@")
}

run_in "$tmp/one" "$ridefit" optimise "$study" -q -o r.yaml >/dev/null ||
  fail "the one-process run failed"
grep -q '^status: optimum' "$tmp/one/r.yaml" || fail "the one-process run found no optimum"
grep -q 'comfort_loss' "$tmp/one/r.yaml" || fail "the study has no friction-blind optimum"
run_in "$tmp/two" ranks 2 "$ridefit" optimise "$study" -q -o r.yaml --json >"$tmp/two.json" ||
  fail "mpirun -np 2 failed"
same_result "$tmp/two" "$tmp/one" "2 ranks"
# --json says how the searches were shared: 4 starts and the friction-blind optimum's 4, then
# both verifications; then 3 trade-off points from 4 starts each, and their verifications.
/usr/bin/env python3 - "$tmp/two.json" <<'PY' || fail "2 ranks: --json does not say how the searches were shared"
import json, sys
r = json.load(open(sys.argv[1]))["ranks"]
assert r["count"] == 2, r
assert [s["searches"] for s in r["stages"]] == [8, 2, 12, 3], r["stages"]
assert r["searches"] == 25 and 0 < r["searches_on_rank0"] < 25, r
assert r["bytes_received_by_rank0"] > 0 and r["bytes_broadcast_by_rank0"] > 0, r
assert all(0 < s["longest_search_s"] <= s["wall_time_s"] for s in r["stages"]), r["stages"]
PY
run_in "$tmp/three" ranks 3 --oversubscribe "$ridefit" optimise "$study" -q --threads 1 \
  -o r.yaml >/dev/null || fail "mpirun -np 3 --oversubscribe failed"
same_result "$tmp/three" "$tmp/one" "3 ranks"
# Rank 0 wrote every evaluation into the journal, each once, whichever rank computed it.
cmp <(sort "$tmp/one/r.journal") <(sort "$tmp/two/r.journal") ||
  fail "2 ranks: the journal holds other evaluations than one process's"

# Ended midway under 2 ranks (SIGTERM to mpirun, which ends its ranks), resumed under 3.
mkdir -p "$tmp/ended"
(cd "$tmp/ended" && exec timeout 300 "${mpi_env[@]}" "$mpiexec" -np 2 "$ridefit" optimise \
  "$study" -q -o r.yaml >/dev/null 2>&1) &
launcher=$!
for _ in $(seq 1 3000); do
  [ "$(wc -l <"$tmp/ended/r.journal" 2>/dev/null || echo 0)" -ge 60 ] && break
  sleep 0.01
done
kill -TERM "$launcher" 2>/dev/null
wait "$launcher"
[ ! -e "$tmp/ended/r.yaml" ] || fail "the run finished before it could be ended"
done_lines=$(wc -l <"$tmp/ended/r.journal")
[ "$done_lines" -ge 60 ] || fail "the ended run left $done_lines journal lines"
for _ in $(seq 1 500); do  # its ranks let go of the journal
  pgrep -f "optimise $study -q -o r.yaml" >/dev/null || break
  sleep 0.01
done
run_in "$tmp/ended" ranks 3 --oversubscribe "$ridefit" optimise "$study" -q --threads 1 \
  -o r.yaml --resume r.journal >/dev/null || fail "the resume under 3 ranks failed"
same_result "$tmp/ended" "$tmp/one" "ended under 2 ranks, resumed under 3"
reused=$(sed -n 's/^reused_evaluations: //p' "$tmp/ended/r.yaml")
[ "${reused:-0}" -gt 0 ] || fail "the resume reused no evaluation of the journal"

# A search that throws (task 3 of the first stage) on whichever rank took it: exit 1 naming the
# rank and the task, no result, the finished searches' evaluations kept; resumed in one process.
mkdir -p "$tmp/thrown"
(cd "$tmp/thrown" && RIDEFIT_TEST_FAULT=throw:2 ranks 2 "$ridefit" optimise "$study" -q \
  --threads 1 -o r.yaml >out.txt 2>&1)
code=$?
[ "$code" -eq 1 ] || fail "a throwing search: exit $code, not 1 (124: it hung)"
grep -q "rank [0-9], run 3: injected failure" "$tmp/thrown/out.txt" || {
  cat "$tmp/thrown/out.txt" >&2
  fail "a throwing search: the message names no rank and run 3"
}
[ ! -e "$tmp/thrown/r.yaml" ] || fail "a throwing search left a result"
[ "$(wc -l <"$tmp/thrown/r.journal")" -gt 10 ] || fail "a throwing search kept no evaluations"
run_in "$tmp/thrown" "$ridefit" optimise "$study" -q -o r.yaml --resume r.journal >/dev/null ||
  fail "the resume in one process failed"
same_result "$tmp/thrown" "$tmp/one" "thrown under 2 ranks, resumed in one process"

# A rank that dies in its first search: the job ends, not hangs.
(cd "$tmp" && RIDEFIT_TEST_FAULT=die:1 ranks 2 "$ridefit" optimise "$study" -q --threads 1 \
  -o died.yaml >/dev/null 2>&1)
code=$?
[ "$code" -ne 0 ] && [ "$code" -ne 124 ] || fail "a dying rank: exit $code (124: it hung)"
[ ! -e "$tmp/died.yaml" ] || fail "a dying rank left a result"
echo "optimise_ranks_test: tunings over 2 and 3 ranks identical to one process; an ended run" \
  "and a throwing search resume under other rank counts to the same optimum"
