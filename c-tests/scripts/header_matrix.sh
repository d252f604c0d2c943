#!/usr/bin/env bash
# The header contract (docs/decisions.md, "The C ABI and the headers"): the generated
# headers compile as C99/C11 and C++98/11/17/20 with gcc and clang, -Wall -Wextra -Werror.
# `--windows`: the same with the MinGW-w64 compilers for 64- and 32-bit Windows (where
# routines and functions are __stdcall), each file also with <windows.h> included first,
# as most Windows programs do.
set -u
src=$(cd "$(dirname "$0")/.." && pwd)
inc="$src/../include"
fail=0; n=0
err=$(mktemp)
trap 'rm -f "$err"' EXIT
run() {
  n=$((n + 1))
  if "$@" 2>"$err"; then echo "ok   $*"; else echo "FAIL $*"; cat "$err"; fail=$((fail + 1)); fi
}
ccs="gcc clang"; cxxs="g++ clang++"; pre=""
if [ "${1:-}" = --windows ]; then
  ccs="x86_64-w64-mingw32-gcc i686-w64-mingw32-gcc"
  cxxs="x86_64-w64-mingw32-g++ i686-w64-mingw32-g++"
  pre="-include windows.h"
fi
for cc in $ccs; do
  command -v $cc >/dev/null || { echo "FAIL: $cc not installed"; fail=$((fail + 1)); continue; }
  for std in c99 c11; do
    run $cc -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$src/header_smoke.c"
    [ -z "$pre" ] || run $cc -std=$std -Wall -Wextra -Werror -fsyntax-only $pre -I"$inc" "$src/header_smoke.c"
  done
done
for cxx in $cxxs; do
  command -v $cxx >/dev/null || { echo "FAIL: $cxx not installed"; fail=$((fail + 1)); continue; }
  for std in c++98 c++11 c++17 c++20; do
    run $cxx -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$src/header_smoke.cpp"
    run $cxx -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" -x c++ "$src/header_smoke.c"
    [ -z "$pre" ] || run $cxx -std=$std -Wall -Wextra -Werror -fsyntax-only $pre -I"$inc" "$src/header_smoke.cpp"
  done
done
echo "header matrix: $((n - fail)) passed, $fail failed"
[ $fail -eq 0 ]
