#!/usr/bin/env bash
# make windows: the Windows DLLs of libMCCLPCI_IMP, cross-built on Debian.
#
#   scripts/windows/build.sh OUT [x64] [x86]      (default: both)
#
# For each architecture, OUT/<arch>/ receives what a Windows user copies:
#   MCCLPCI_IMP.dll, MCCLPCI_IMP3.dll  the library under both names the vendor used
#   MCCLPCI_IMP.def, MCCLPCI_IMP3.def  the exports, for MSVC: lib /def:MCCLPCI_IMP.def
#                                      /machine:x64 (or x86) makes MCCLPCI_IMP.lib
#   libMCCLPCI_IMP.dll.a, libMCCLPCI_IMP3.dll.a   MinGW import libraries
#   include/                           the headers
# x86: every MCC_* function is stdcall, exported under its undecorated name (as the
# vendor's 32-bit DLL and VB6 Declare want); the .def files list the decorated names
# (MCC_CloseGroup@4) so that an import library maps what C callers compiled against
# the __stdcall prototypes reference (_MCC_CloseGroup@4) to that export. mcl_* and
# MCCL_Sim* are cdecl, as their headers declare no convention.
#
# How (docs/windows.md): Debian's Rust (rustc-web, with the std sources of rust-web-src)
# builds std for the target with -Zbuild-std, linking with MinGW-w64. i686 needs the
# startup objects rsbegin.o/rsend.o that rustup would ship: they are compiled here from
# the std sources. The packages: scripts/install-deps.sh --windows.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: build.sh OUT [x64] [x86]}
shift
mkdir -p "$out"
out=$(cd "$out" && pwd)
arches=("$@")
[ ${#arches[@]} -gt 0 ] || arches=(x64 x86)

# Debian's compiler, not rustup's (whose proxies come first on PATH).
RUSTC=/usr/bin/rustc
CARGO=/usr/bin/cargo
for tool in "$RUSTC" "$CARGO"; do
  [ -x "$tool" ] || { echo "build.sh: $tool missing: run scripts/install-deps.sh --windows" >&2; exit 1; }
done
export RUSTC RUSTDOC=/usr/bin/rustdoc
# -Zbuild-std is unstable: Debian's compiler is a stable one, told to allow it.
export RUSTC_BOOTSTRAP=1
export CARGO_TARGET_DIR="$out/cargo"
std_src=$("$RUSTC" --print sysroot)/lib/rustlib/src/rust/library
[ -d "$std_src/std" ] || { echo "build.sh: no std sources in $std_src (package rust-web-src)" >&2; exit 1; }

for arch in "${arches[@]}"; do
  case $arch in
    x64) triple=x86_64-pc-windows-gnu; mingw=x86_64-w64-mingw32 ;;
    x86) triple=i686-pc-windows-gnu; mingw=i686-w64-mingw32 ;;
    *) echo "build.sh: unknown architecture $arch (x64, x86)" >&2; exit 2 ;;
  esac
  t0=$(date +%s)
  var=$(echo "$triple" | tr 'a-z-' 'A-Z_')
  export "CARGO_TARGET_${var}_LINKER=$mingw-gcc"
  if [ "$arch" = x86 ]; then
    rt="$out/rtstartup/$triple"
    mkdir -p "$rt"
    for obj in rsbegin rsend; do
      [ "$rt/$obj.o" -nt "$std_src/rtstartup/$obj.rs" ] ||
        "$RUSTC" --target "$triple" --emit=obj -C panic=abort -O -o "$rt/$obj.o" "$std_src/rtstartup/$obj.rs"
    done
    export "CARGO_TARGET_${var}_RUSTFLAGS=-L native=$rt"
  fi
  (cd "$root" && "$CARGO" build --release --lib -q -Zbuild-std=std,panic_unwind --target "$triple")
  built="$CARGO_TARGET_DIR/$triple/release/MCCLPCI_IMP.dll"

  dist="$out/$arch"
  rm -rf "$dist"
  mkdir -p "$dist/include"
  # The debug information stays in the cargo directory's copy.
  "$mingw-strip" --strip-debug -o "$dist/MCCLPCI_IMP.dll" "$built"
  cp "$dist/MCCLPCI_IMP.dll" "$dist/MCCLPCI_IMP3.dll"
  cp "$root"/include/*.h "$dist/include/"

  # The exports, each under the name a C caller's object file references without its
  # leading underscore: NAME@N for stdcall (x86), NAME otherwise.
  exports=$("$mingw-objdump" -p "$built" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' |
            sed -n 's/^[[:space:]]*\[ *[0-9]*\] //p')
  decorated=$("$mingw-nm" "$built" | awk '$2 == "T" {print $3}' | grep '@[0-9]*$' | sed 's/^_//' | sort -u || true)
  for lib in MCCLPCI_IMP MCCLPCI_IMP3; do
    {
      echo "LIBRARY $lib.dll"
      echo "EXPORTS"
      for name in $exports; do
        d=$(grep -m1 "^$name@[0-9]*\$" <<<"$decorated" || true)
        echo "    ${d:-$name}"
      done
    } >"$dist/$lib.def"
    "$mingw-dlltool" -k -d "$dist/$lib.def" -D "$lib.dll" -l "$dist/lib$lib.dll.a"
  done
  if [ "$arch" = x86 ]; then
    # The calling conventions: every MCC_* function stdcall, mcl_* and MCCL_Sim* cdecl.
    not_stdcall=$(grep -E '^ +MCC_' "$dist/MCCLPCI_IMP.def" | grep -v '@' || true)
    not_cdecl=$(grep -E '^ +(mcl_|MCCL_Sim)' "$dist/MCCLPCI_IMP.def" | grep '@' || true)
    if [ -n "$not_stdcall$not_cdecl" ]; then
      echo "build.sh: wrong calling convention: $not_stdcall $not_cdecl" >&2
      exit 1
    fi
  fi
  # The headers declare exactly what each DLL exports, under undecorated names.
  for dll in MCCLPCI_IMP MCCLPCI_IMP3; do
    (cd "$root" && "$CARGO" run --release -q -p mccl-bindings -- --exports "$dist/$dll.dll")
  done
  echo "windows $arch: $dist ($(($(date +%s) - t0)) s)"
done
