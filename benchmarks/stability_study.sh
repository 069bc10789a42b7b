#!/usr/bin/env bash
# Stability study of the face-wise constant multiplier ("where methods
# fail"): every case is run with the bubbles (the scheme) and without them
# (Contact/Bubbles = false: the bubble unknowns fixed to zero), on B2 Tresca
# 2D (quads, triangles, distorted quads, locally refined quads), B2 Tresca 3D
# (hexahedra, distorted hexahedra) and B1 (inclined crack, Coulomb), and over
# four decades of the complementarity parameter beta. One line per run:
#
#   status    ok, or FAIL(lvK:reason) when the program stopped at level K
#             (singular: UMFPACK found the Newton Jacobian singular;
#             no conv.: Newton failed after beta reductions and step cuts)
#   levels    levels completed
#   newton    Newton iterations per level (total over load steps)
#   b/10,dm   how often the solver divided beta by 10 on active-set cycling
#             or stagnation, and its damped steps (summed over levels)
#   grad_u, l_hm12  err_grad_u, err_lambda_hm12 at the finest completed level,
#   err_lambda_l2 at every completed level,
#   open      open faces at the finest completed level (exact: 0 in B1, B2),
#   max_jump, jump_in, tv  oscillation of lambda_n between neighbouring faces at the
#             finest completed level, relative to the mean |lambda_n|
#             (benchmarks/stability_plot.py metrics; exact: 0, lambda_n is
#             constant in B1 and B2): largest jump, largest jump between
#             faces in the middle 80 % of the fracture, total variation.
#
# Full logs and outputs go to output/stability/NAME-{bub,nob}/; then
#   /usr/bin/python3 benchmarks/stability_plot.py plot output/stability
# draws benchmarks/stability-lambda.png.
#
# usage: benchmarks/stability_study.sh [path/to/polyfrac] [--quick]
#   --quick: the mesh and B1 cases only, fewer levels (about 1 minute).
# Takes about 5 minutes on 2 shared cores (B1 level 2 dominates).
set -uo pipefail
cd "$(dirname "$0")/.."
program=build/polyfrac
quick=0
for a in "$@"; do
  case $a in
    --quick) quick=1 ;;
    *) program=$a ;;
  esac
done
root=$PWD/output/stability
mkdir -p "$root"
python=/usr/bin/python3

printf '%-24s %-3s %-24s %-2s %-16s %-6s %-9s %-9s %-44s %-4s %-8s %-6s %s\n' \
  case bub status lv newton b/10,dm grad_u l_hm12 "err_lambda_l2 per level" open max_jump jump_in tv

run() { # name levels scene overrides...
  local name=$1 levels=$2 scene=$3; shift 3
  for variant in bub nob; do
    local dir=$root/$name-$variant
    local bubbles=true
    [ $variant = nob ] && bubbles=false
    rm -rf "$dir"
    local args=(--set "Output/Output directory=$dir"
                --set "Output/Print timings=false"
                --set "Convergence study/Number of refinement levels=$levels"
                --set "Contact/Bubbles=$bubbles")
    for o in "$@"; do args+=(--set "$o"); done
    mkdir -p "$dir"
    "$program" "prm/$scene" "${args[@]}" > "$dir.log" 2>&1
    local rc=$?
    local status=ok
    if [ $rc -ne 0 ]; then
      local level reason
      level=$(grep -c '^Level ' "$dir.log")
      level=$((level - 1))
      if grep -q 'UMFPACK.*error status 1' "$dir.log"; then reason="singular"
      elif grep -q 'did not converge' "$dir.log"; then reason="no conv."
      else reason="rc $rc"; fi
      status="FAIL(lv$level:$reason)"
    fi
    local newton nbeta ndamp
    newton=$(grep '^Newton iterations:' "$dir.log" | awk '{printf "%s%s", sep, $3; sep=","}')
    nbeta=$(grep -c 'complementarity parameter divided' "$dir.log")
    ndamp=$(grep -c 'damped step' "$dir.log")
    local csv=$dir/convergence.csv lv=0 eg=- eh=- el=-
    if [ -f "$csv" ]; then
      lv=$(($(wc -l < "$csv") - 1))
      eg=$(awk -F, 'END {print ($6 == "" ? "-" : sprintf("%.2e", $6))}' "$csv")
      eh=$(awk -F, 'END {printf "%.2e", $8}' "$csv")
      el=$(awk -F, 'NR > 1 {printf "%s%.2e", sep, $9; sep=","}' "$csv")
    fi
    local m
    m=$($python benchmarks/stability_plot.py metrics "$dir")
    printf '%-24s %-3s %-24s %-2s %-16s %-6s %-9s %-9s %-44s %-4s %-8s %-6s %s\n' \
      "$name" "$variant" "$status" "$lv" "${newton:--}" "$nbeta,$ndamp" "$eg" "$eh" "$el" \
      "$(echo "$m" | awk '{print $6}')" "$(echo "$m" | awk '{print $8}')" \
      "$(echo "$m" | awk '{print $12}')" "$(echo "$m" | awk '{print $10}')"
  done
}

b2=b2-2d-tresca.prm
b3=b2-3d-tresca.prm
# The scene ships the settings of its 48^3 run; here UMFPACK from 2^3 on,
# with the default Newton tolerance.
b3_small=("Mesh/Subdivisions=2, 2, 2" "Linear solver/Method=direct"
  "Linear solver/Smoother sweeps=3" "Nonlinear solver/Tolerance=1e-10")
b1=b1-inclined-crack.prm
L2=5; L3=3; L1=3
[ $quick = 1 ] && { L2=3; L3=2; L1=2; }

echo "# meshes"
run b2-2d-quads        $L2 $b2
run b2-2d-triangles    $L2 $b2 "Mesh/Cell type=simplex"
run b2-2d-distorted    $L2 $b2 "Mesh/Distortion=0.3"
run b2-2d-local        $((L2 - 1)) $b2 "Mesh/Local refinements=2"
run b2-3d-hexes        $L3 $b3 "${b3_small[@]}"
run b2-3d-distorted    $L3 $b3 "${b3_small[@]}" "Mesh/Distortion=0.3"
run b1                 $L1 $b1
[ $quick = 1 ] && exit 0

# beta over five decades; auto = (2 mu + lambda)/h_sigma: 3/h_sigma for B2
# (6 .. 96 over levels 0..4), 3e10/h_sigma for B1 (3e11 .. 1.2e12 on the crack).
echo "# beta (B2: auto = 3/h_sigma = 6..48; B1: auto = 3e10/h_sigma = 3e11..1.2e12)"
for beta in 0.1 10 1000 1e5; do
  run b2-2d-quads-beta$beta     4 $b2 "Contact/Complementarity parameter=$beta"
done
for beta in 0.1 10 1000 1e5; do
  run b2-2d-distorted-beta$beta 4 $b2 "Mesh/Distortion=0.3" "Contact/Complementarity parameter=$beta"
done
for beta in 0.1 1000; do
  run b2-3d-hexes-beta$beta     2 $b3 "${b3_small[@]}" "Contact/Complementarity parameter=$beta"
done
for beta in 1e9 1e11 1e13 1e15; do
  run b1-beta$beta              2 $b1 "Contact/Complementarity parameter=$beta"
done
