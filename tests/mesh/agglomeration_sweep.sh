#!/usr/bin/env bash
# METIS agglomeration by 2 to 16 cells per polytope on 2D boxes of
# quadrilaterals, triangles and distorted quadrilaterals (issue 28): every
# run must converge with order >= 0.9 in err_grad_u, the least-squares slope
# of log err_grad_u against log h over its levels (h, the largest
# agglomerate, jumps from level to level: the order between two levels
# alone ranges from 0.83 to 1.23 on one family whose slope is 1.0).
# Agglomerates far from convex used to be refused for negative weights
# although the scheme converges on them; the weights are now made
# non-negative (MeshGeometry, doc/scheme.md §4).
#
# Three levels from 32 x 32 cells (on 16 x 16 the coarsest agglomerates of
# 13 cells are pre-asymptotic: order 0.83). 3D is not swept here: on the
# levels a test can afford (8^3 and 16^3 hexahedra) agglomerates of 16
# cells are pre-asymptotic too (order 0.48 between them).
#
# usage: agglomeration_sweep.sh POLYFRAC SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
scene=$source/prm/smooth-2d.prm
runs=0 orders="" lowest=99
for mesh in "Cell type=hypercube" "Cell type=simplex" "Distortion=0.2"; do
  for n in 2 3 4 6 8 11 16; do
    log="$work/run-$runs.log"
    if ! "$program" "$scene" --set "Mesh/$mesh" \
        --set "Mesh/Subdivisions=32, 32" \
        --set "Mesh/Cells per polytope=$n" \
        --set "Convergence study/Number of refinement levels=3" \
        --set "Output/Write VTU=false" --set "Output/Print timings=false" \
        --set "Output/Output directory=$work/out" > "$log" 2>&1; then
      echo "FAILED: $mesh, Cells per polytope = $n:"
      tail -5 "$log"
      exit 1
    fi
    # The slope of log err_grad_u (column 6) against log h (column 2).
    order=$(awk -F, 'NR > 1 { x = log($2); y = log($6); n++; sx += x;
      sy += y; sxx += x * x; sxy += x * y }
      END { if (n < 2) print "none";
            else printf "%.3f", (n * sxy - sx * sy) / (n * sxx - sx * sx) }' \
      "$work/out/convergence.csv")
    if [ "$order" = none ] || awk "BEGIN { exit !($order < 0.9) }"; then
      echo "FAILED: $mesh, Cells per polytope = $n: order $order < 0.9"
      cat "$work/out/convergence.csv"
      exit 1
    fi
    orders="$orders $order"
    [ "$(awk "BEGIN { print ($order < $lowest) }")" = 1 ] && lowest=$order
    runs=$((runs + 1))
  done
done
echo "$runs agglomerated runs in 2D converge in err_grad_u with orders$orders"
echo "lowest order: $lowest (at least 0.9 asked)"
