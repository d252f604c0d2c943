#!/usr/bin/env bash
# Runs one Windows test program under Wine and says whether it passed.
#
#   wine-run.sh [--rust | --pass REGEX | --status] ARCH DLLDIR PREFIX PROGRAM.exe [ARGS...]
#
# ARCH is x64 (wine64) or x86 (wine, 32-bit); DLLDIR holds the DLL the program loads
# (MCCLPCI_IMP.dll, MCCLPCI_IMP3.dll: ours, or another under the same name), put on its
# DLL search path after the program's own folder; PREFIX is the Wine prefix of
# wine-prefix.sh. The program's output is passed through. It passed when it exited with 0
# AND printed the pass line a crash cannot print: a test program of c-tests/ ends with
# "<name>: N passed, 0 failed" (N > 0), a Rust test binary (--rust) with "test result:
# ok. N passed; 0 failed", another program with a line matching REGEX (--pass, an
# extended regular expression). The exit status alone is not enough: under Wine a
# crashing test runner may still exit 0. --status takes it alone, for a program whose
# output a later step checks (a scenario whose trace is compared with a recorded one).
set -uo pipefail
mode=c
case "${1:-}" in
  --rust) mode=rust; shift ;;
  --pass) mode=custom; custom_pass=${2:?--pass needs a regular expression}; shift 2 ;;
  --status) mode=status; shift ;;
esac
[ $# -ge 4 ] || { echo "usage: wine-run.sh [--rust | --pass REGEX | --status] ARCH DLLDIR PREFIX PROGRAM [ARGS...]" >&2; exit 2; }
arch=$1 dlls=$2 prefix=$3
shift 3
case $arch in
  x64) wine=${MCCL_WINE64:-/usr/lib/wine/wine64} ;;
  # Wine's 32-bit backtrace code crashes on a panic (one a test provokes on purpose).
  x86) wine=${MCCL_WINE32:-/usr/lib/wine/wine}; export RUST_BACKTRACE=0 ;;
  *) echo "wine-run.sh: ARCH is x64 or x86, not $arch" >&2; exit 2 ;;
esac
export WINEPREFIX="$prefix" WINEDEBUG=${WINEDEBUG:--all} WINEDLLOVERRIDES="mscoree,mshtml="
# Wine's drive Z: is the Unix root.
export WINEPATH="Z:$(echo "$dlls" | tr / '\\')"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# Into a file, not a pipe: Wine's service processes (winedevice.exe, ...) inherit the
# program's output and outlive it while the Wine server runs, so a pipe would stay open.
"$wine" "$@" >"$out" 2>&1 </dev/null
status=$?
cat "$out"
if [ "$mode" = rust ]; then
  pass='^test result: ok\. [0-9]+ passed; 0 failed'
  fail='^test result: FAILED'
elif [ "$mode" = custom ]; then
  pass=$custom_pass
  fail=''
elif [ "$mode" = status ]; then
  pass='' fail=''
else
  pass=': [1-9][0-9]* passed, 0 failed$'
  fail=': [0-9]+ passed, [1-9][0-9]* failed$'
fi
tr -d '\r' <"$out" >"$out.lf" && mv "$out.lf" "$out"
if [ "$status" -ne 0 ]; then
  echo "wine-run.sh: $(basename "$1") exited with $status" >&2
  exit 1
fi
[ "$mode" != status ] || exit 0
if { [ -n "$fail" ] && grep -Eq "$fail" "$out"; } || ! grep -Eq "$pass" "$out"; then
  echo "wine-run.sh: $(basename "$1") exited with 0 but printed no pass line (or a failure)" >&2
  exit 1
fi
