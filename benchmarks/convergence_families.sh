#!/usr/bin/env bash
# Convergence study per mesh family (issue "Foundation", acceptance):
# err_grad_u over 4 levels for the smooth solution (2D, 3D) and B2 with the
# exact traction prescribed (2D, 3D), on every mesh family. Prints the
# convergence table of each run; full outputs go to output/families/.
#
# usage: benchmarks/convergence_families.sh [path/to/polyfrac]
set -euo pipefail
cd "$(dirname "$0")/.."
program=${1:-build/polyfrac}
levels=${LEVELS:-4}

run() { # name scene overrides...
  local name=$1 scene=$2; shift 2
  local args=(--set "Output/Output directory=output/families/$name"
              --set "Output/Write VTU=false"
              --set "Convergence study/Number of refinement levels=$levels")
  for o in "$@"; do args+=(--set "$o"); done
  echo "=== $name"
  "$program" "prm/$scene" "${args[@]}" > "output/families/$name.log" 2>&1 ||
    { tail -5 "output/families/$name.log"; return 1; }
  sed -n '/^level/,$p' "output/families/$name.log"
}
mkdir -p output/families

for scene in smooth-2d b2-2d; do
  [ $scene = b2-2d ] && base="Mesh/Subdivisions=8, 8" || base="Mesh/Subdivisions=8, 8"
  run $scene-quads $scene.prm "$base"
  run $scene-triangles $scene.prm "$base" "Mesh/Cell type=simplex"
  run $scene-distorted $scene.prm "$base" "Mesh/Distortion=0.3"
  run $scene-smooth-distorted $scene.prm "$base" "Mesh/Distortion=0.3" "Mesh/Distortion type=smooth"
  run $scene-local-refinement $scene.prm "$base" "Mesh/Local refinements=1"
  run $scene-agglomerated $scene.prm "$base" "Mesh/Cells per polytope=4"
done
for scene in smooth-3d b2-3d; do
  base="Mesh/Subdivisions=4, 4, 4"
  run $scene-hexes $scene.prm "$base"
  run $scene-tets $scene.prm "$base" "Mesh/Cell type=simplex"
  run $scene-distorted $scene.prm "$base" "Mesh/Distortion=0.3"
  run $scene-smooth-distorted $scene.prm "$base" "Mesh/Distortion=0.3" "Mesh/Distortion type=smooth"
  run $scene-local-refinement $scene.prm "$base" "Mesh/Local refinements=1"
  run $scene-agglomerated $scene.prm "$base" "Mesh/Cells per polytope=4"
done
