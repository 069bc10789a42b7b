#!/usr/bin/env bash
# used_parameters.prm re-runs as it is, from another directory: the scene
# prm/b5-closed-crack.prm (a gmsh mesh file and an output directory given
# relative to the parameter file), one level, is run once; then its
# used_parameters.prm is run from / (only the output directory redirected).
# The mesh file must be found (absolute paths) and convergence.csv must be
# the same but for its wall time column (the last). Exits non-zero if not.
#
# usage: used_parameters_rerun.sh POLYFRAC SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$program" "$source/prm/b5-closed-crack.prm" \
  --set "Convergence study/Number of refinement levels=1" \
  --set "Output/Output directory=$work/first" > "$work/first.log"
grep -q "set File name *= /" "$work/first/used_parameters.prm" ||
  { echo "used_parameters.prm names the mesh file by a relative path"; exit 1; }
(cd / && "$program" "$work/first/used_parameters.prm" \
  --set "Output/Output directory=$work/again" > "$work/again.log")
without_wall_time() { rev "$1" | cut -d, -f2- | rev; }
if ! diff <(without_wall_time "$work/first/convergence.csv") \
          <(without_wall_time "$work/again/convergence.csv"); then
  echo "the re-run of used_parameters.prm differs"
  exit 1
fi
echo "used_parameters.prm re-runs from / with the same convergence.csv"
