#!/usr/bin/env bash
# Digest of every example program's trace and events file, on the fast and stepped clocks.
# Refactors and speed work must leave these byte for byte the same: run this on the build
# of the old commit and of the new one and compare the two outputs (`diff`).
#   scripts/trace-digest.sh [build-dir]   (default: build)
set -u
build=${1:-build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for src in c-tests/examples/*.cpp; do
  name=$(basename "$src" .cpp)
  prog="$build/c-tests/$name"
  [ -x "$prog" ] || continue
  # The machines CTest runs these programs on (c-tests/CMakeLists.txt).
  case $name in
    GoHome) sim=c-tests/sim/home_x.toml ;;
    InPosCheck|PCLControl) sim=c-tests/sim/lag_x.toml ;;
    *) sim= ;;
  esac
  for clock in fast stepped; do
    MCCL_SIM=$sim MCCL_CLOCK=$clock MCCL_TRACE="$tmp/t.csv" "$prog" >/dev/null 2>&1
    rc=$?
    t=$(md5sum < "$tmp/t.csv" 2>/dev/null | cut -c1-32)
    e=$(md5sum < "$tmp/t.events.csv" 2>/dev/null | cut -c1-32)
    echo "$name $clock exit=$rc trace=$t events=$e"
    rm -f "$tmp/t.csv" "$tmp/t.events.csv"
  done
done
