#!/usr/bin/env bash
# Runs a scene serially and on N ranks (mpirun) and checks that
# - the convergence tables agree (columns level to err_fracture_pressure of
#   convergence.csv; wall times differ) to the relative tolerance TOL, and
#   so do the time series (all but the iteration counts, the energy
#   residual and the wall time);
# - the N-rank run wrote, for every VTU step of the serial run, a .pvtu
#   record listed by the .pvd, whose pieces (at most N) exist and hold data;
# - the line probes and region integrals agree to TOL;
# - only rank 0 printed (the N-rank output has the serial one's lines).
# Exits non-zero, naming what fails.
#
# usage: compare_ranks.sh POLYFRAC WORKDIR N TOL FILE.prm [--set A=B ...]
set -euo pipefail
polyfrac=$1 workdir=$2 n=$3 tolerance=$4 prm=$5
shift 5
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$workdir" && mkdir -p "$workdir"
"$polyfrac" "$prm" "$@" --set "Output/Output directory=$workdir/serial" \
  > "$workdir/serial.log" 2>&1 || { cat "$workdir/serial.log"; exit 1; }
mpirun -np "$n" --oversubscribe "$polyfrac" "$prm" "$@" \
  --set "Output/Output directory=$workdir/ranks" > "$workdir/ranks.log" 2>&1 ||
  { cat "$workdir/ranks.log"; echo "the $n-rank run failed"; exit 1; }

for run in serial ranks; do
  cut -d, -f1-11 "$workdir/$run/convergence.csv" > "$workdir/$run.csv"
done
numdiff -q -s ', \t\n' -r "$tolerance" -a 1e-14 "$workdir/serial.csv" \
  "$workdir/ranks.csv" ||
  { cat "$workdir/serial.csv" "$workdir/ranks.csv";
    echo "The convergence tables differ (relative tolerance $tolerance)."; exit 1; }

# The time series: step, time, time step, cuts, the contact states, the
# mean aperture, the mean fracture and the injection pressure, the open and
# slipping areas, the pressure error (columns 1-4 and 7-15; the iteration
# counts of iterative solves may differ, so may the energy residual, which
# is round-off, and the wall time).
for series in "$workdir"/serial/time_series*.csv; do
  [ -e "$series" ] || continue
  name=$(basename "$series")
  [ -s "$workdir/ranks/$name" ] || { echo "the $n-rank run wrote no $name"; exit 1; }
  for run in serial ranks; do
    cut -d, -f1-4,7-15 "$workdir/$run/$name" > "$workdir/$run-$name"
  done
  numdiff -q -s ', \t\n' -r "$tolerance" -a 1e-14 "$workdir/serial-$name" \
    "$workdir/ranks-$name" ||
    { cat "$workdir/serial-$name" "$workdir/ranks-$name";
      echo "$name differs (relative tolerance $tolerance)."; exit 1; }
done

# The line probes and region integrals (Output/Line probes, Region
# integrals): every value, with the same tolerance (a point on a face
# shared by two cells takes the same cell's value on any number of ranks).
probes=0
for table in "$workdir"/serial/line-*.csv "$workdir"/serial/regions-*.csv; do
  [ -e "$table" ] || continue
  name=$(basename "$table")
  [ -s "$workdir/ranks/$name" ] || { echo "the $n-rank run wrote no $name"; exit 1; }
  numdiff -q -s ', \t\n' -r "$tolerance" -a 1e-12 "$table" "$workdir/ranks/$name" ||
    { numdiff -s ', \t\n' -r "$tolerance" -a 1e-12 "$table" \
        "$workdir/ranks/$name" | tail -5;
      echo "$name differs (relative tolerance $tolerance)."; exit 1; }
  probes=$((probes + 1))
done

steps=0
for vtu in "$workdir"/serial/*-[0-9][0-9][0-9][0-9].vtu; do
  name=$(basename "$vtu" .vtu)
  pvtu=$workdir/ranks/$name.pvtu
  [ -s "$pvtu" ] || { echo "no $name.pvtu for $name.vtu"; exit 1; }
  grep -q "$name.pvtu" "$workdir/ranks/${name%-*}.pvd" ||
    { echo "${name%-*}.pvd does not list $name.pvtu"; exit 1; }
  # The pieces of the ranks with something to write (vtu_pieces_2_ranks
  # checks that a rank without writes none).
  pieces=$(grep -o 'Source="[^"]*"' "$pvtu" | sed 's/Source="\(.*\)"/\1/')
  [ -n "$pieces" ] && [ "$(echo "$pieces" | wc -l)" -le "$n" ] ||
    { echo "$name.pvtu lists no piece, or more than $n"; exit 1; }
  for piece in $pieces; do
    [ -s "$workdir/ranks/$piece" ] ||
      { echo "$name.pvtu: piece $piece missing"; exit 1; }
  done
  steps=$((steps + 1))
done
[ "$steps" -gt 0 ] || { echo "the serial run wrote no VTU step"; exit 1; }

if [ "$(grep -c '^Level ' "$workdir/ranks.log")" != \
     "$(grep -c '^Level ' "$workdir/serial.log")" ]; then
  echo "the $n-rank run printed its levels more than once"; exit 1
fi
echo "Same convergence table on $n ranks (relative tolerance $tolerance):" \
  "$(($(wc -l < "$workdir/serial.csv") - 1)) levels; $steps VTU steps as" \
  ".pvtu records of at most $n pieces; $probes probe and region tables"
