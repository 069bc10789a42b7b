#!/usr/bin/env bash
# Sets PolyFrac up on a Debian bookworm machine: installs the missing Debian
# packages (as root), configures and builds the Release build in build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libdeal.ii-dev openmpi-bin libgmsh-dev gmsh numdiff cmake make g++ perl time doxygen python3-meshio valgrind procps)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
echo "Built build/polyfrac (log: build.log)"
