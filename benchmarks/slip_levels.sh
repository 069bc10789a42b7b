#!/usr/bin/env bash
# The slip scene (prm/poromechanics-2d-slip.prm, tight rock k = 1e-17 m²,
# its loads, injection and Δt = 1 s unchanged) on the shipped mesh and its
# uniform refinements (levels 0..L-1: the 16² squares cut into triangles,
# refined k more times, then the cells next to the fault Mesh/Fracture
# refinements more times; Refine time step with mesh stays false): per level
# the mean aperture, the mean fracture pressure (the injection pressure: the
# source is uniform along the fault), the open and slipping faces and the
# slipped length (slip_area) at the end (t = 10 s), the wall time, and each
# level's difference to the finest level and to the next. Prints a markdown
# table. Further arguments go to polyfrac, e.g.
# --set "Mesh/Fracture refinements=0" for uniform meshes.
#
# usage: benchmarks/slip_levels.sh [LEVELS=4] [path/to/polyfrac] [--set ...]
# (output in $SLIP_LEVELS_OUTPUT, default output/slip-levels)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
levels=${1:-4}
program=${2:-$root/build/polyfrac}
shift $(($# < 2 ? $# : 2))
out=${SLIP_LEVELS_OUTPUT:-$root/output/slip-levels}
mkdir -p "$out"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/time -f "wall %e s, peak memory %M KB" "$program" \
  "$root/prm/poromechanics-2d-slip.prm" \
  --set "Convergence study/Number of refinement levels=$levels" \
  --set "Output/Write VTU=false" \
  --set "Output/Output directory=$out" "$@" > "$out/log" 2> "$out/time" ||
  { tail -20 "$out/log"; cat "$out/time"; exit 1; }
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
tail -1 "$out/time"
/usr/bin/python3 - "$out" "$levels" <<'PY'
import csv, math, sys
out, levels = sys.argv[1], int(sys.argv[2])
rows = []
for k in range(levels):
    series = list(csv.DictReader(open(f"{out}/time_series-level-{k}.csv")))
    last = series[-1]
    # The fault (length √2) is cut into equal faces on every level.
    faces = sum(int(last[n]) for n in ("n_open", "n_stick", "n_slip"))
    rows.append(dict(level=k, aperture=float(last["mean_aperture"]),
                     pressure=float(last["mean_fracture_pressure"]),
                     slip=int(last["n_slip"]), open=int(last["n_open"]),
                     slipped=float(last["slip_area"]),
                     face=math.sqrt(2) / faces,
                     wall=sum(float(r["wall_seconds"]) for r in series)))
fine = rows[-1]
print("| level | mean aperture (m) | vs finest | mean p_f (MPa) | vs finest |"
      " open / slip faces | slipped length (m) | vs finest (faces of this level) | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %d | %.5e | %+.2f %% | %.4f | %+.2f %% | %d / %d | %.4f | %+.2f | %.1f |" % (
        r["level"], r["aperture"], 100 * (r["aperture"] / fine["aperture"] - 1),
        r["pressure"] / 1e6, 100 * (r["pressure"] / fine["pressure"] - 1),
        r["open"], r["slip"], r["slipped"],
        (r["slipped"] - fine["slipped"]) / r["face"], r["wall"]))
print("level-to-level differences (aperture, pressure):",
      ", ".join("%.2e / %.2e" % (abs(b["aperture"] - a["aperture"]),
                                 abs(b["pressure"] - a["pressure"]))
                for a, b in zip(rows, rows[1:])))
PY
