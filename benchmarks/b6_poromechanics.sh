#!/usr/bin/env bash
# B6, the seed's 3D poromechanical scene (prm/b6-poromechanics-3d.prm,
# benchmarks/B6.md): runs the whole schedule (20 steps of 500 s) on the
# 47k-tetrahedra mesh, or on the 127k one with --fine, and prints the wall
# time, the CPU time, the peak memory and the machine's load before and
# after, then the per-step table (time_series-level-0.csv: coupling and
# Newton iterations, open/stick/slip faces, mean aperture and fracture
# pressure, energy residual, wall seconds per step). The table is copied to
# benchmarks/b6-poromechanics-47k.csv (or -127k.csv) and the fracture
# fields of the last step are drawn by render_fracture_jumps.py into
# benchmarks/b6-poro-47k-*.png (opening, slip, states, fracture pressure).
# --coarse runs the 17k mesh of the mesh study (geo/b6-network-coarse.geo).
# The schedule takes hours: 100-720 s per step at 47k on one thread, about
# 10 min per step at 127k (benchmarks/B6.md, 2026-12-02); a run stopped by
# SIGTERM or SIGINT goes on with polyfrac FILE --resume (a checkpoint after
# every step).
#
# usage: benchmarks/b6_poromechanics.sh [--fine | --coarse] [path/to/polyfrac]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

mesh=geo/b6-network.geo
label=47k
if [ "${1:-}" = "--fine" ]; then
  mesh=geo/b6-network-fine.geo
  label=127k
  shift
elif [ "${1:-}" = "--coarse" ]; then
  mesh=geo/b6-network-coarse.geo
  label=17k
  shift
fi
program=${1:-$root/build/polyfrac}
out=$root/output/b6-poromechanics-$label
mkdir -p "$root/output"

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/time -f "wall %e s, CPU %U s, peak memory %M KB" \
  "$program" "$root/prm/b6-poromechanics-3d.prm" \
  --set "Mesh/File name=$mesh" \
  --set "Output/Output directory=$out" > "$out.log" 2> "$out.time" ||
  { tail -20 "$out.log"; cat "$out.time"; exit 1; }
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
tail -1 "$out.time"
grep "^Step" "$out.log"
cp "$out/time_series-level-0.csv" "$root/benchmarks/b6-poromechanics-$label.csv"
column -s, -t < "$out/time_series-level-0.csv"
/usr/bin/python3 "$root/benchmarks/render_fracture_jumps.py" \
  "$root/benchmarks/b6-poro-$label" "$out/fractures-level-0.pvd" \
  --labels "$label tetrahedra, t = 10000 s"
