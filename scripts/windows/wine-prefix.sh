#!/usr/bin/env bash
# The Wine prefix the Windows tests run in:  scripts/windows/wine-prefix.sh PREFIX
#
# Made fresh when missing or made by another Wine installation (a prefix created before
# wine32 was installed fails with "could not load kernel32.dll"); a stamp file records
# which. Wine 8 lacks bcryptprimitives.dll, whose ProcessPrng Rust's standard library
# imports: a stand-in (bcryptprimitives.c) goes into the prefix's system directories
# when Wine has none. Nothing here is shipped: it only makes Wine a Windows 10 for the
# tests.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
prefix=${1:?usage: wine-prefix.sh PREFIX}
export WINEPREFIX="$prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
stamp="$(wine --version) $(dpkg-query -W -f='${Version}' wine32:i386 2>/dev/null || echo no-wine32)"
if [ "$(cat "$prefix/.mccl-stamp" 2>/dev/null)" != "$stamp" ]; then
  rm -rf "$prefix"
  mkdir -p "$prefix"
  wineboot -i >/dev/null 2>&1 || true
  wineserver -w
  [ -f "$prefix/drive_c/windows/system32/kernel32.dll" ] ||
    { echo "wine-prefix.sh: wineboot did not make $prefix" >&2; exit 1; }
  echo "$stamp" >"$prefix/.mccl-stamp"
fi
sys="$prefix/drive_c/windows"
for d in "system32:x86_64-w64-mingw32" "syswow64:i686-w64-mingw32"; do
  dir=$sys/${d%%:*}
  mingw=${d#*:}
  [ -d "$dir" ] || continue
  ours="$dir/bcryptprimitives.mccl-stand-in"
  if [ ! -f "$dir/bcryptprimitives.dll" ] ||
     { [ -f "$ours" ] && [ "$here/bcryptprimitives.c" -nt "$ours" ]; }; then
    "$mingw-gcc" -O2 -shared -Wall -Wextra -Werror -Wl,--kill-at -o "$dir/bcryptprimitives.dll" \
      "$here/bcryptprimitives.c" -ladvapi32
    touch "$ours"
  fi
done
