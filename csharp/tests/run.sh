#!/usr/bin/env bash
# Compiles the C# binding (csharp/MCCL.cs) with the Mono tests (csharp/tests/*.cs) and runs
# them against a built libMCCLPCI_IMP.so:
#   csharp/tests/run.sh <path/to/libMCCLPCI_IMP.so> [out-dir] [test-name-filter...]
# The library is found through LD_LIBRARY_PATH (its directory); Mono maps
# [DllImport("MCCLPCI_IMP.dll")] to libMCCLPCI_IMP.so there. MCCL_CLOCK defaults to fast.
set -u
lib=${1:?usage: run.sh <libMCCLPCI_IMP.so> [out-dir] [filter...]}
out=${2:-$(mktemp -d)}
here=$(cd "$(dirname "$0")" && pwd)
for tool in mcs mono; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "FAIL: '$tool' not found; install Debian's mono-mcs and mono-runtime (scripts/install-deps.sh)"
    exit 1
  fi
done
if [ ! -f "$lib" ]; then
  echo "FAIL: $lib does not exist (build the library first)"
  exit 1
fi
mkdir -p "$out"
if ! mcs -langversion:7.2 -warnaserror+ -nologo -out:"$out/mccl_mono.exe" \
    "$here/../MCCL.cs" "$here"/*.cs; then
  echo "FAIL: mcs could not compile MCCL.cs and the tests"
  exit 1
fi
export MCCL_CLOCK=${MCCL_CLOCK:-fast}
export LD_LIBRARY_PATH="$(cd "$(dirname "$lib")" && pwd)${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exec mono --debug "$out/mccl_mono.exe" "${@:3}"
