# What the rank tests share, sourced as `. mpi_test_common.sh NAME RIDEFIT SOURCE_DIR MPI MPIEXEC`:
# sets ridefit, src and mpiexec, skips (exit 77) in a build without MPI, makes a temporary folder
# $tmp removed at exit, and defines fail MESSAGE and ranks N [mpirun options] COMMAND, every
# mpirun under a timeout (rank_timeout seconds, 120 unless set) so that nothing may hang.
test_name=$1
ridefit=$2
src=$3
if [ "$4" != "ON" ] || [ -z "${5:-}" ]; then
  echo "$test_name: skipped: ridefit was built without MPI (RIDEFIT_WITH_MPI=OFF, or Open MPI" \
    "not found: apt install libopenmpi-dev openmpi-bin)"
  exit 77
fi
mpiexec=$5
# Root in containers and CI; no cross-memory attach there either.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "$test_name: $*" >&2
  exit 1
}
# Under tools/test --sanitize, Open MPI's own allocations outlive MPI_Finalize and LeakSanitizer
# would report them for every rank (none is ridefit's): the ranks run without leak detection,
# with ASan's other checks and UBSan still on. The one-process runs keep it.
mpi_env=()
if [ -n "${ASAN_OPTIONS:-}" ]; then
  mpi_env=(env "ASAN_OPTIONS=$ASAN_OPTIONS:detect_leaks=0")
fi
ranks() {  # ranks N [mpirun options] COMMAND…, ended after ${rank_timeout:-120} s
  local n=$1
  shift
  timeout "${rank_timeout:-120}" "${mpi_env[@]}" "$mpiexec" -np "$n" "$@"
}
