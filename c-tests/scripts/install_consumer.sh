#!/usr/bin/env bash
# `cmake --install` into a scratch prefix, then build and run a program against the
# installed copy twice: through find_package(MCCL) and through pkg-config. Also checks the
# .NET probing names point at the library.
set -euo pipefail
build=$1; src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
lib=$(ls -d "$tmp"/prefix/lib*/ | head -1)
for f in libMCCLPCI_IMP.so libMCCLPCI_IMP.a libMCCLPCI_IMP.dll.so MCCLPCI_IMP.dll.so pkgconfig/mccl.pc cmake/MCCL/MCCLConfig.cmake; do
  [ -e "$lib/$f" ] || { echo "missing after install: $lib$f"; exit 1; }
done
[ "$(readlink "$lib/MCCLPCI_IMP.dll.so")" = libMCCLPCI_IMP.so ] || { echo "bad .NET alias"; exit 1; }
"$tmp/prefix/bin/mccl-trace" --help >/dev/null || { echo "mccl-trace not installed or not runnable"; exit 1; }
"$tmp/prefix/bin/mc3b-app" --help >/dev/null || { echo "mc3b-app not installed or not runnable"; exit 1; }
for h in MCCL.h MCCL_Fun.h mccl.h mcl.h; do
  [ -e "$tmp/prefix/include/mccl/$h" ] || { echo "missing header $h"; exit 1; }
done
mkdir "$tmp/consumer"
cp "$src/initsys_c99.c" "$src/check.h" "$tmp/consumer/"
cat > "$tmp/consumer/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.16)
project(consumer C)
find_package(MCCL REQUIRED)
add_executable(consumer initsys_c99.c)
target_link_libraries(consumer PRIVATE MCCL::MCCLPCI_IMP)
CM
cmake -S "$tmp/consumer" -B "$tmp/consumer/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/consumer/build" >/dev/null
LD_LIBRARY_PATH="$lib" MCCL_CLOCK=fast "$tmp/consumer/build/consumer"
flags=$(PKG_CONFIG_PATH="$lib/pkgconfig" pkg-config --cflags --libs mccl)
cc -o "$tmp/pc" "$src/initsys_c99.c" -I"$src" $flags
LD_LIBRARY_PATH="$lib" MCCL_CLOCK=fast "$tmp/pc"
echo "install: find_package and pkg-config consumers built and ran"
