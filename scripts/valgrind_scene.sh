#!/usr/bin/env bash
# valgrind memcheck of a scene (the parameter file given first, e.g.
# prm/default.prm; all its levels, VTU output into a temporary directory)
# with the Release build in build/ (bash scripts/setup.sh builds it). Exits non-zero on any invalid access, use
# of uninitialised memory or definite leak. Leaks of OpenMPI's start-up and
# shut-down are suppressed: Debian's openmpi-valgrind.supp and
# tests/sanitizers/valgrind.supp. Further arguments go to polyfrac, e.g.
# --set "Convergence study/Number of refinement levels=1".
# Without --track-origins (44 s against 66 s for the equilibrium and the
# first step, Release, idle machine): an uninitialised value is still
# reported, with the stack of its use; add --track-origins=yes to the
# command below to see where it was allocated.
set -euo pipefail
cd "$(dirname "$0")/.."

[ $# -ge 1 ] && [ -f "$1" ] ||
  { echo "usage: $0 SCENE.prm [--set Subsection/Entry=value ...]"; exit 1; }
scene=$1
shift

mpi_suppressions=/usr/share/openmpi/openmpi-valgrind.supp
[ -f "$mpi_suppressions" ] ||
  { echo "$mpi_suppressions is missing: apt-get install openmpi-common"; exit 1; }
[ -x build/polyfrac ] ||
  { echo "build/polyfrac is missing: run bash scripts/setup.sh first"; exit 1; }

output=$(mktemp -d)
trap 'rm -rf "$output"' EXIT
# Components stay loaded, so that leak stacks name OpenMPI's functions.
export OMPI_MCA_mca_base_component_disable_dlclose=1
valgrind --tool=memcheck --error-exitcode=1 \
  --num-callers=50 --leak-check=full --show-leak-kinds=definite \
  --errors-for-leak-kinds=definite \
  --suppressions="$mpi_suppressions" \
  --suppressions=tests/sanitizers/valgrind.supp \
  build/polyfrac "$scene" \
  --set "Output/Output directory=$output" "$@"
