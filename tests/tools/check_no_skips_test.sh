#!/usr/bin/env bash
# tools/check-no-skips on made-up ctest logs and listings: a skipped test fails it, except the
# noexec temporary folder's; a missing group of optional tests fails it and names the packages.
# Usage: check_no_skips_test.sh SOURCE_DIR
set -euo pipefail
check="$1/tools/check-no-skips"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "check_no_skips_test: $*" >&2; exit 1; }

# A build whose listing has every group.
mkdir "$tmp/full" "$tmp/bare"
cat > "$tmp/full/CTestTestfile.cmake" <<'CTEST'
add_test(python.test_model true)
add_test(mpi.SweepOverRanks true)
add_test(MatScipy.ReadsWhatSimulateWrites true)
CTEST
echo 'add_test(Unit.Only true)' > "$tmp/bare/CTestTestfile.cmake"

printf '100%% tests passed, 0 tests failed out of 3\n' > "$tmp/clean.log"
"$check" "$tmp/full" "$tmp/clean.log" || fail "a clean run was refused"

printf 'The following tests did not run:\n\t3 - MatScipy.ReadsWhatSimulateWrites (Skipped)\n\n' \
  > "$tmp/skipped.log"
if "$check" "$tmp/full" "$tmp/skipped.log" 2> "$tmp/err"; then fail "a skipped test passed"; fi
grep -q "MatScipy.ReadsWhatSimulateWrites (Skipped)" "$tmp/err" || fail "the skip was not named"

printf 'The following tests did not run:\n\t7 - TemporaryFiles.GnuplotDiesWithItsParent (Skipped)\n\n' \
  > "$tmp/noexec.log"
"$check" "$tmp/full" "$tmp/noexec.log" 2> /dev/null || fail "the noexec skip was refused"

if "$check" "$tmp/bare" "$tmp/clean.log" 2> "$tmp/err"; then fail "missing groups passed"; fi
grep -q "python3-numpy" "$tmp/err" || fail "the Python group's packages were not named"
grep -q "openmpi-bin" "$tmp/err" || fail "the MPI group's packages were not named"
echo "check_no_skips_test: ok"
