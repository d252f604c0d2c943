#!/usr/bin/env bash
# make windows-test: the Windows DLLs of `make windows`, tested under Wine.
#
#   scripts/windows/test.sh OUT [HOST_TARGET_DIR]
#
# OUT is the folder build.sh made (e.g. build/windows); HOST_TARGET_DIR the cargo target
# directory for the Linux tools run here (default OUT/host-cargo; make passes the Linux
# build's, which has them already).
#
# 1. the headers compile with MinGW-w64 for x64 and x86 (header_matrix.sh --windows), and
#    the C# and VB bindings declare exactly what the DLLs export, undecorated, with the
#    calling conventions they use (mccl-bindings --verify on each DLL);
# 2. for x64 (wine64) and x86 (wine32): every C/C++ test program of c-tests/, built by
#    CMake with MinGW-w64 against OUT/<arch> (cmake/mingw-wine.cmake), run by CTest in
#    the same variants (fast and stepped clock, machine files) as on Linux; each run
#    passes only with exit status 0 and its "N passed, 0 failed" line (wine-run.sh);
# 3. the Rust unit tests of the library, its core crate and the MC3B crate, built for
#    x86_64-pc-windows-gnu under wine64 and for i686-pc-windows-gnu under wine32 (each
#    crate's "test result: ok" line is checked, not only cargo's status).
# Each step's time is printed at the end. What Wine cannot show (real Windows timing, a
# real COM port, VB6) is in docs/windows.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: test.sh OUT}
out=$(cd "$out" && pwd)
host_target=${2:-$out/host-cargo}
prefix="$out/wineprefix"
times=()
step() { times+=("$(printf '%-44s %4d s' "$1" "$2")"); }
now() { date +%s; }

for arch in x64 x86; do
  [ -f "$out/$arch/MCCLPCI_IMP.dll" ] ||
    { echo "test.sh: $out/$arch/MCCLPCI_IMP.dll missing: run make windows first" >&2; exit 1; }
done

t=$(now)
"$root/scripts/windows/wine-prefix.sh" "$prefix"
step "Wine prefix" $(($(now) - t))

# One Wine server for all runs (a server per program would cost its start-up each time,
# and two programs starting at once would race to start it).
export WINEPREFIX="$prefix" WINEDEBUG=-all
wineserver -p >/dev/null 2>&1 </dev/null
trap 'WINEPREFIX="$prefix" wineserver -k 2>/dev/null || true' EXIT

t=$(now)
"$root/c-tests/scripts/header_matrix.sh" --windows | tail -1
step "headers, MinGW x64 and x86" $(($(now) - t))

t=$(now)
for arch in x64 x86; do
  echo "bindings against the $arch DLL:"
  (cd "$root" && CARGO_TARGET_DIR="$host_target" cargo run --release -q -p mccl-bindings -- \
    --verify "$out/$arch/MCCLPCI_IMP.dll") | sed 's/^/  /'
done
step "C#/VB bindings against the DLLs' exports" $(($(now) - t))

summary=()
for arch in x64 x86; do
  tree="$out/test-$arch"
  t=$(now)
  cmake -S "$root" -B "$tree" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-wine.cmake" \
    -DMCCL_WINDOWS_ARCH=$arch -DMCCL_WINDOWS_DIR="$out/$arch" -DMCCL_WINE_PREFIX="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$tree" -j2 >/dev/null
  step "C/C++ programs, MinGW $arch" $(($(now) - t))
  t=$(now)
  log="$tree/ctest.log"
  status=0
  ctest --test-dir "$tree" -j2 --output-on-failure >"$log" 2>&1 || status=$?
  wine=wine64; [ $arch = x64 ] || wine=wine32
  line=$(grep -E 'tests passed, [0-9]+ tests failed out of' "$log" || true)
  step "C/C++ programs under $wine" $(($(now) - t))
  if [ $status -ne 0 ] || ! grep -q '^100% tests passed, 0 tests failed' <<<"$line"; then
    cat "$log"
    echo "test.sh: the C/C++ programs failed under $wine" >&2
    exit 1
  fi
  summary+=("$wine: $line")
done

export RUSTC=/usr/bin/rustc RUSTDOC=/usr/bin/rustdoc RUSTC_BOOTSTRAP=1
export CARGO_TARGET_DIR="$out/cargo"
for arch in x64 x86; do
  t=$(now)
  case $arch in
    x64) triple=x86_64-pc-windows-gnu; mingw=x86_64-w64-mingw32; wine=wine64 ;;
    x86) triple=i686-pc-windows-gnu; mingw=i686-w64-mingw32; wine=wine32 ;;
  esac
  var=$(echo "$triple" | tr 'a-z-' 'A-Z_')
  export "CARGO_TARGET_${var}_LINKER=$mingw-gcc"
  export "CARGO_TARGET_${var}_RUNNER=$root/scripts/windows/wine-run.sh --rust $arch $out/$arch $prefix"
  # The startup objects build.sh made for i686.
  [ $arch = x64 ] || export "CARGO_TARGET_${var}_RUSTFLAGS=-L native=$out/rtstartup/$triple"
  log="$out/rust-unit-tests-$arch.log"
  status=0
  # The unit tests of the library and of its crates: the core (planner, machine, card)
  # and the MC3B board's (protocol, client, emulator).
  (cd "$root" && /usr/bin/cargo test --release --lib -q -Zbuild-std=std,panic_unwind \
    -p mcclpci_imp -p mccl-core -p mc3b --target "$triple") >"$log" 2>&1 || status=$?
  line=$(grep -E '^test result:' "$log" || true)
  step "Rust unit tests, build and $wine" $(($(now) - t))
  if [ $status -ne 0 ] || [ "$(grep -c . <<<"$line")" -ne 3 ] ||
     [ "$(grep -c '^test result: ok\. [0-9]* passed; 0 failed' <<<"$line")" -ne 3 ]; then
    cat "$log"
    echo "test.sh: the Rust unit tests failed under $wine" >&2
    exit 1
  fi
  summary+=("$wine: Rust unit tests: $(tr '\n' ' ' <<<"$line")")
done

echo "Windows tests:"
printf '  %s\n' "${summary[@]}"
echo "Windows test times:"
printf '  %s\n' "${times[@]}"
