#!/usr/bin/env bash
# scripts/plot_time_series.py draws summary.png from a run's time series:
# the default scene to t = 2 s (equilibrium and 2 steps) gives a PNG of 4
# panels and 3 steps; a directory without a time series is refused with a
# message, and no PNG is written there.
# usage: summary_plot.sh POLYFRAC SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work/run" "$work/empty"
"$program" "$source/prm/default.prm" --set "Time/End time=2" \
  --set "Output/Write VTU=false" --set "Output/Output directory=$work/run" \
  > "$work/run.log"
said=$(/usr/bin/python3 "$source/scripts/plot_time_series.py" "$work/run")
echo "$said"
[ "$said" = "Wrote $work/run/summary.png: 4 panels, 3 steps" ] ||
  { echo "FAILED: unexpected report"; exit 1; }
# A PNG (its signature), of a figure's size.
[ "$(head -c 8 "$work/run/summary.png" | od -An -tx1 | tr -d ' \n')" = \
  "89504e470d0a1a0a" ] || { echo "FAILED: summary.png is not a PNG"; exit 1; }
[ "$(stat -c %s "$work/run/summary.png")" -gt 10000 ] ||
  { echo "FAILED: summary.png is too small to hold the panels"; exit 1; }
if /usr/bin/python3 "$source/scripts/plot_time_series.py" "$work/empty" \
    > "$work/empty.log" 2>&1; then
  echo "FAILED: a directory without a time series was accepted"; exit 1
fi
grep -q "no time_series-level-K.csv" "$work/empty.log" ||
  { echo "FAILED: no message for the empty directory"; exit 1; }
[ ! -e "$work/empty/summary.png" ] ||
  { echo "FAILED: a PNG was written for nothing"; exit 1; }
echo "summary.png checked"
