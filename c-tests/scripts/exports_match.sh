#!/usr/bin/env bash
# The headers declare exactly the functions the library exports: compares the
# MCC_* prototypes of include/MCCL_Fun.h with `nm -D` of the built library, and checks that
# the library exports nothing without one of our prefixes. Given a Windows DLL, reads its
# export table (`objdump -p`) instead and also checks that every name is undecorated
# (no `_` prefix, no `@N` suffix: what GetProcAddress, VB6 Declare and .def files use).
set -u
lib=$1
inc=$(cd "$(dirname "$0")/../../include" && pwd)
status=0
if objdump -f "$lib" 2>/dev/null | grep -q 'file format pei-'; then
  exported=$(objdump -p "$lib" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' |
             sed -n 's/^[[:space:]]*\[ *[0-9]*\] //p' | sort)
  decorated=$(echo "$exported" | grep -E '^_|@' || true)
  if [ -n "$decorated" ]; then
    echo "decorated export names:"; echo "$decorated"; status=1
  fi
else
  exported=$(nm -D --defined-only "$lib" | awk '$2 == "T" {print $3}' | sort)
fi
declared=$( (cat "$inc"/MCCL_Fun.h | grep -o 'MCC_CALL [A-Za-z0-9_]*(' | sed 's/MCC_CALL //; s/(//';
             grep -o '^int mcl_[a-z_]*(' "$inc"/mcl.h | sed 's/^int //; s/(//';
             grep -o '^int MCCL_Sim[A-Za-z]*(' "$inc"/MCCL_Sim.h | sed 's/^int //; s/(//') | sort)
mcc_exported=$(echo "$exported" | grep -E '^(MCC_|mcl_|MCCL_Sim)' || true)
if [ "$mcc_exported" != "$declared" ]; then
  echo "declared vs exported differ (< header only, > library only):"
  diff <(echo "$declared") <(echo "$mcc_exported")
  status=1
fi
stray=$(echo "$exported" | grep -v -E '^(MCC_|MCCL_|mcl_)' || true)
if [ -n "$stray" ]; then
  echo "unexpected exported symbols:"; echo "$stray"; status=1
fi
echo "exports of $(basename "$lib"): $(echo "$mcc_exported" | grep -c .) MCC_*/mcl_*/MCCL_Sim* functions exported and declared"
exit $status
