#!/usr/bin/env bash
# The header contract (docs/decisions.md, "The C ABI and the headers"): the generated
# headers compile as C99/C11 and C++98/11/17/20 with gcc and clang, -Wall -Wextra -Werror.
set -u
src=$(cd "$(dirname "$0")/.." && pwd)
inc="$src/../include"
fail=0; n=0
run() {
  n=$((n + 1))
  if "$@" 2>/tmp/mccl_hdr_err.txt; then echo "ok   $*"; else echo "FAIL $*"; cat /tmp/mccl_hdr_err.txt; fail=$((fail + 1)); fi
}
for cc in gcc clang; do
  command -v $cc >/dev/null || { echo "FAIL: $cc not installed"; fail=$((fail + 1)); continue; }
  for std in c99 c11; do
    run $cc -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$src/header_smoke.c"
  done
done
for cxx in g++ clang++; do
  command -v $cxx >/dev/null || { echo "FAIL: $cxx not installed"; fail=$((fail + 1)); continue; }
  for std in c++98 c++11 c++17 c++20; do
    run $cxx -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$src/header_smoke.cpp"
    run $cxx -std=$std -Wall -Wextra -Werror -fsyntax-only -I"$inc" -x c++ "$src/header_smoke.c"
  done
done
echo "header matrix: $((n - fail)) passed, $fail failed"
[ $fail -eq 0 ]
