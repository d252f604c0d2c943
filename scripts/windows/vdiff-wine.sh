#!/bin/sh
# The differential suite's runner (c-tests/vendor) as vtrace.py replay calls it —
# `vdiff-wine.sh LIBRARY SCENARIO OUT` — for the Windows vdiff.exe under wine64: the
# drop-in test (c-tests/CMakeLists.txt). MCCL_VDIFF_EXE, MCCL_WINDOWS_DIR and
# MCCL_WINE_PREFIX come from CTest; LIBRARY is a DLL name found on the DLL folder's path.
exec "$(dirname "$0")/wine-run.sh" --status x64 "$MCCL_WINDOWS_DIR" "$MCCL_WINE_PREFIX" \
  "$MCCL_VDIFF_EXE" "$@"
