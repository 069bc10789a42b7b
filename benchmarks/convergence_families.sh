#!/usr/bin/env bash
# Convergence study per mesh family: err_grad_u (and the jump and multiplier
# errors) over 4 levels on every mesh family for the smooth solution (2D,
# 3D), B2 with the exact traction prescribed (elasticity) and B2 with Tresca
# contact. Prints the convergence table of each run (with the wall time per
# level from convergence.csv); full outputs go to output/families/.
#
# B2 3D with Tresca contact runs from 8^3 to 64^3 with the condensed AMG
# Newton steps (Linear solver/Method = AMG): its multiplier error is
# pre-asymptotic below 16^3 (benchmarks/README.md).
#
# usage: [SCENES="smooth-2d b2-3d-tresca ..."] [FAMILIES="hexes tets ..."]
#        benchmarks/convergence_families.sh [path/to/polyfrac]
set -euo pipefail
cd "$(dirname "$0")/.."
program=${1:-build/polyfrac}
levels=${LEVELS:-4}

run() { # name scene overrides...
  local name=$1 scene=$2; shift 2
  local family=${name#${scene%.prm}-}
  [[ -z ${FAMILIES:-} || " $FAMILIES " == *" $family "* ]] || return 0
  local args=(--set "Output/Output directory=$PWD/output/families/$name"
              --set "Output/Write VTU=false"
              --set "Convergence study/Number of refinement levels=$levels")
  for o in "$@"; do args+=(--set "$o"); done
  echo "=== $name"
  /usr/bin/time -f "maximum resident memory: %M kB" -o "output/families/$name.memory" \
    "$program" "prm/$scene" "${args[@]}" > "output/families/$name.log" 2>&1 ||
    { tail -5 "output/families/$name.log"; return 1; }
  sed -n '/^level/,$p' "output/families/$name.log"
  echo "wall seconds per level: $(cut -d, -f11 "output/families/$name/convergence.csv" | tail -n +2 | tr '\n' ' ')"
  echo "Newton iterations per level: $(cut -d, -f10 "output/families/$name/convergence.csv" | tail -n +2 | tr '\n' ' ')"
  cat "output/families/$name.memory"
}
mkdir -p output/families

scenes=${SCENES:-smooth-2d b2-2d b2-2d-tresca smooth-3d b2-3d b2-3d-tresca}
for scene in $scenes; do
  case $scene in
    *-2d*) base="Mesh/Subdivisions=8, 8" ;;
    b2-3d-tresca) base="Mesh/Subdivisions=8, 8, 8" ;;  # 4 levels: up to 64^3
    *) base="Mesh/Subdivisions=4, 4, 4" ;;
  esac
  if [[ $scene == *-2d* ]]; then
  run $scene-quads $scene.prm "$base"
  run $scene-triangles $scene.prm "$base" "Mesh/Cell type=simplex"
  run $scene-distorted $scene.prm "$base" "Mesh/Distortion=0.3"
  run $scene-smooth-distorted $scene.prm "$base" "Mesh/Distortion=0.3" "Mesh/Distortion type=smooth"
  run $scene-local-refinement $scene.prm "$base" "Mesh/Local refinements=1"
  run $scene-agglomerated $scene.prm "$base" "Mesh/Cells per polytope=4"
  else
  # B2 with contact: refine the layer of cells on the + side of the stick
  # half of the fracture (x < 0.25, z < 0) once.
  box="Mesh/Local refinement box=0, -1, -1 : 0.25, 1, 0"
  [ "$scene" = b2-3d-tresca ] || box="Mesh/Local refinement box=-0.5, -0.5, -0.5 : 0.5, 0.5, 0.5"
  solver="Linear solver/Method=direct"
  [ "$scene" = b2-3d-tresca ] && solver="Linear solver/Method=AMG"
  run $scene-hexes $scene.prm "$base" "$solver"
  run $scene-tets $scene.prm "$base" "$solver" "Mesh/Cell type=simplex"
  run $scene-distorted $scene.prm "$base" "$solver" "Mesh/Distortion=0.3"
  run $scene-smooth-distorted $scene.prm "$base" "$solver" "Mesh/Distortion=0.3" "Mesh/Distortion type=smooth"
  run $scene-local-refinement $scene.prm "$base" "$solver" "Mesh/Local refinements=1" "$box"
  run $scene-agglomerated $scene.prm "$base" "$solver" "Mesh/Cells per polytope=4"
  fi
done
