#!/usr/bin/env bash
# Compares two runs of one scene: as it is (A) and with extra --set
# arguments (B). CHECK is one of
#   equal=TOL            B's convergence table equals A's (columns level to
#                        err_fracture_pressure of convergence.csv; the Newton
#                        iterations and wall times may differ) to the
#                        relative tolerance TOL, by numdiff;
#   series=TOL           B's time series equals A's (step, time, time step,
#                        contact states, mean aperture and fracture
#                        pressure of time_series-level-0.csv; the
#                        iterations may differ) to the relative tolerance TOL;
#   smaller=COLUMN:F     on every level, B's error COLUMN is at most F times
#                        A's (e.g. B adds a stabilisation A lacks);
#   cheaper=COLUMN       B's last level has a smaller error COLUMN than A's
#                        last level with fewer unknowns (e.g. B refines
#                        where the error is, A everywhere).
# CHECK@TEXT also asks that B's output contain TEXT (that B took the path
# the comparison is about, e.g. "FGMRES iteration").
# Exits non-zero, printing both tables, when the check fails.
#
# usage: compare_runs.sh POLYFRAC WORKDIR CHECK FILE.prm [--set A=B ...]
#                        -- [--set C=D ...]
set -euo pipefail
polyfrac=$1 workdir=$2 check=$3 prm=$4
shift 4
expected_text=
if [[ $check == *@* ]]; then
  expected_text=${check#*@} check=${check%%@*}
fi
common=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do common+=("$1"); shift; done
[ $# -gt 0 ] && shift

mkdir -p "$workdir"
run() {
  local dir=$workdir/$1
  shift
  "$polyfrac" "$prm" "${common[@]}" --set "Output/Output directory=$dir" \
    --set "Output/Write VTU=false" "$@" > "$dir.log" 2>&1 ||
    { cat "$dir.log"; echo "run $dir failed"; exit 1; }
  cut -d, -f1-11 "$dir/convergence.csv" > "$dir.csv"
  if [ -f "$dir/time_series-level-0.csv" ]; then
    cut -d, -f1-3,7-11 "$dir/time_series-level-0.csv" > "$dir-series.csv"
  fi
}
run a
run b "$@"
if [ -n "$expected_text" ] && ! grep -q "$expected_text" "$workdir/b.log"; then
  cat "$workdir/b.log"
  echo "B's output does not contain '$expected_text'"
  exit 1
fi
a=$workdir/a.csv b=$workdir/b.csv
fail() {
  echo "$1"
  echo "A:"; cat "$a"; echo "B ($*):"; cat "$b"
  exit 1
}

case $check in
  equal=*)
    tolerance=${check#equal=}
    numdiff -q -s ', \t\n' -r "$tolerance" -a 1e-14 "$a" "$b" ||
      fail "The runs differ (relative tolerance $tolerance)."
    echo "Same convergence table (relative tolerance $tolerance):" \
      "$(($(wc -l < "$a") - 1)) levels"
    ;;
  series=*)
    tolerance=${check#series=}
    a=$workdir/a-series.csv b=$workdir/b-series.csv
    numdiff -q -s ', \t\n' -r "$tolerance" -a 1e-14 "$a" "$b" ||
      fail "The time series differ (relative tolerance $tolerance)."
    echo "Same time series (relative tolerance $tolerance):" \
      "$(($(wc -l < "$a") - 1)) steps"
    ;;
  smaller=*)
    spec=${check#smaller=} column=${spec%%:*} factor=${spec#*:}
    paste -d, "$a" "$b" | awk -F, -v name="$column" -v factor="$factor" '
      NR == 1 { for (i = 1; i <= NF / 2; ++i) if ($i == name) c = i
                if (!c) { print "no column " name; exit 1 }
                next }
      { n = NF / 2
        if ($c == "" || $(c + n) == "" || !($(c + n) <= factor * $c)) {
          print "level " $1 ": " name " " $(c + n) " is not below " factor \
                " x " $c; exit 1 }
        printf "level %d: %s %s <= %s x %s\n", $1, name, $(c + n), factor, $c }' ||
      fail "The check $check fails."
    ;;
  cheaper=*)
    column=${check#cheaper=}
    { head -1 "$a"; tail -1 "$a"; tail -1 "$b"; } | awk -F, -v name="$column" '
      NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == name) c = i
                                             if ($i == "n_dofs") n = i }
                if (!c) { print "no column " name; exit 1 }
                next }
      NR == 2 { ea = $c; na = $n; next }
      { if (ea == "" || $c == "" || !($c < ea) || !($n < na)) {
          print "B ends at " name " " $c " with " $n " unknowns, A at " ea \
                " with " na; exit 1 }
        printf "B: %s %s with %d unknowns < A: %s with %d\n", name, $c, $n,
               ea, na }' ||
      fail "The check $check fails."
    ;;
  *) echo "unknown check $check"; exit 2 ;;
esac
