#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, only those missing:
# cmake (build), clang (header compile matrix), mono (C# tests), socat (serial tests),
# valgrind (leak checks), chromium, chromium-driver and python3 (the browser panel's test).
#
# --windows adds what `make windows` and the Windows tests need: Debian's Rust with its
# std sources (rustc-web, cargo-web, rust-web-src: std is built for the Windows targets
# from them), the MinGW-w64 C and C++ compilers for x64 and x86, and Wine (wine64, and
# wine32 from the i386 architecture, which is enabled for it).
#
# Runs apt-get as root, or through sudo.
set -euo pipefail
pkgs=(cmake clang mono-mcs mono-runtime socat valgrind chromium chromium-driver python3)
windows=0
for a in "$@"; do
  case $a in
    --windows) windows=1 ;;
    *) echo "install-deps.sh: unknown option $a (--windows)" >&2; exit 2 ;;
  esac
done
if [ $windows -eq 1 ]; then
  pkgs+=(rustc-web cargo-web rust-web-src g++-mingw-w64-x86-64 g++-mingw-w64-i686
         wine wine64 wine32:i386)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
if [ $windows -eq 1 ] && ! dpkg --print-foreign-architectures | grep -qx i386; then
  $sudo dpkg --add-architecture i386
fi
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
