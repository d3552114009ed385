#!/usr/bin/env bash
# tools/diagnosis-benchmark: its draw is fixed by the seed and holds what the benchmark promises
# (every group, both kinds, at least 30 % of the hidden effects near the detection limit), its
# bad flags are exit 2, and a 10-case run of vehicle spectra (seed 3; the rig's loop diagnoses
# take minutes each) scores: no case stops with an error, every control quiet, the evidence's most
# probable explanation exactly right in at least 8 of 10, the verdict in at least 5 (measured
# 2026-12-06: 9 and 6; docs/diagnosis.md), the Brier score of the verdict's p at most 0.1 (0.014);
# its --calibrate recomputes every explanation's probability from the run's --json as the
# diagnosis weighed it (the Python weighing against weigh_explanations) and refuses a folder
# without a run.
# Usage: diagnosis_benchmark_test.sh RIDEFIT SOURCE_DIR
set -euo pipefail
ridefit="$1"
bench="$2/tools/diagnosis-benchmark"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "diagnosis_benchmark_test: $*" >&2; exit 1; }

"$bench" --list --cases 100 --seed 7 > "$tmp/a.json"
"$bench" --list --cases 100 --seed 7 > "$tmp/b.json"
cmp -s "$tmp/a.json" "$tmp/b.json" || fail "the same seed drew different cases"
"$bench" --list --cases 100 --seed 8 > "$tmp/c.json"
cmp -s "$tmp/a.json" "$tmp/c.json" && fail "another seed drew the same cases"
python3 - "$tmp/a.json" <<'PY' || fail "the draw of 100 cases misses a promise"
import json, sys
cases = json.load(open(sys.argv[1]))
groups = {(c["kind"], c["group"]) for c in cases}
for kind in ("vehicle", "rig"):
    for group in ("control", "single", "pair", "outside"):
        assert (kind, group) in groups, (kind, group)
hidden = [c for c in cases if c["effects"]]
near = sum(c["near_limit"] for c in hidden)
assert near >= 0.3 * len(hidden), (near, len(hidden))
assert {c["noise"] for c in cases} == {0.005, 0.02, 0.05}
PY

for bad in "--cases 0" "--jobs 0" "--kinds road"; do
  status=0
  "$bench" $bad --no-build --ridefit "$ridefit" --out "$tmp/bad" 2> "$tmp/err" || status=$?
  [ "$status" -eq 2 ] || fail "$bad: exit $status, expected 2"
  grep -q -- "${bad%% *}" "$tmp/err" || fail "$bad: the message does not name the flag"
done

"$bench" --cases 10 --seed 3 --kinds vehicle --no-build --ridefit "$ridefit" --out "$tmp/run" \
  > "$tmp/run.log"
python3 - "$tmp/run/score.json" <<'PY' || { cat "$tmp/run.log"; fail "the 10-case score"; }
import json, sys
s = json.load(open(sys.argv[1]))
assert s["cases"] == 10 and s["errors"] == 0, s
assert s["controls_quiet"] == s["controls"], s
assert s["most_probable_right"] >= 8, s
assert s["right"] >= 5, s
assert s["brier_verdict_p"] <= 0.1, s
PY

"$bench" --calibrate --cases 10 --seed 3 --kinds vehicle --out "$tmp/run" > "$tmp/cal.log" \
  || { cat "$tmp/cal.log"; fail "--calibrate on the 10-case run"; }
python3 - "$tmp/run/calibration.json" <<'PY' || { cat "$tmp/cal.log"; fail "the calibration"; }
import json, sys
c = json.load(open(sys.argv[1]))
assert c["cases"] == 10, c
assert c["largest_difference_at_shipped"] < 1e-9, c
assert len(c["grid"]) == 30 and c["brier_at_best"] <= c["brier_at_shipped"], c
PY
status=0
"$bench" --calibrate --cases 10 --seed 3 --out "$tmp/empty" 2> "$tmp/err" || status=$?
[ "$status" -eq 2 ] || fail "--calibrate on an empty folder: exit $status, expected 2"
grep -q "no finished cases" "$tmp/err" || fail "--calibrate on an empty folder: $(cat "$tmp/err")"
