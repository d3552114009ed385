#!/bin/bash
# Installs ridefit from BUILD_DIR into a temporary prefix, then configures, builds and runs the
# consumer project (tests/package/consumer) against it, as a user's project would:
# find_package(ridefit CONFIG) must give the three libraries with their dependencies, and the
# installed `ridefit` must report the project's version.
# usage: consumer_test.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build=$1
src=$2
version=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
step() {  # step NAME COMMAND...: runs the command, shows its log if it fails
  local name=$1
  shift
  if ! "$@" >"$tmp/$name.log" 2>&1; then
    echo "consumer_test: $name failed:" >&2
    tail -40 "$tmp/$name.log" >&2
    exit 1
  fi
}
step install cmake --install "$build" --prefix "$tmp/prefix"
step configure cmake -S "$src/tests/package/consumer" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$tmp/prefix"
step build cmake --build "$tmp/build" -j1
"$tmp/build/consumer" "$src/datasets/vehicles/passat_b8_front.yaml"
"$tmp/prefix/bin/ridefit" --version | grep -qx "ridefit $version" || {
  echo "consumer_test: the installed ridefit --version does not say 'ridefit $version'" >&2
  exit 1
}
test -f "$tmp/prefix/include/ridefit/version.h"
test -f "$tmp/prefix/lib/cmake/ridefit/ridefitConfigVersion.cmake"
echo "consumer_test: built and ran a consumer against ridefit $version installed in a temporary prefix"
