#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, only those missing:
# cmake (build), clang (header compile matrix), mono (C# tests), socat (serial tests),
# valgrind (leak checks), chromium, chromium-driver and python3 (the browser panel's test).
# Runs apt-get as root, or through sudo.
set -euo pipefail
pkgs=(cmake clang mono-mcs mono-runtime socat valgrind chromium chromium-driver python3)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
