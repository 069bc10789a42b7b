#!/usr/bin/env bash
# A scene as shipped, timed: runs `polyfrac FILE.prm` (under `mpirun -np
# RANKS` when RANKS > 1) RUNS times and prints, per run, the wall time of
# the whole run (MPI's start included), the peak resident memory of the
# largest process, the last level's unknowns and errors (convergence.csv);
# then the median wall and the load average before and after. Issue 9's
# bounds are for `prm/b2-3d-tresca.prm` on 2 ranks (err_u <= 1e-3 within
# 30 s) and `prm/b1-inclined-crack.prm` on 1 (within 1.5 s).
#
# usage: benchmarks/shipped_scene.sh FILE.prm [RANKS [RUNS [POLYFRAC]]]
#        (from the source directory; RANKS 1, RUNS 3, POLYFRAC
#        build/polyfrac by default)
set -euo pipefail
prm=$1 ranks=${2:-1} runs=${3:-3} program=${4:-build/polyfrac}
[ -f "$prm" ] || { echo "no parameter file $prm"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

launcher=()
[ "$ranks" -gt 1 ] && launcher=(mpirun -np "$ranks")
echo "$prm on $ranks rank(s), $runs runs; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
walls=()
for run in $(seq "$runs"); do
  /usr/bin/time -f "%e %M" -o "$work/time" "${launcher[@]}" "$program" \
    "$prm" --set "Output/Output directory=$work/out" > "$work/log" 2>&1 ||
    { tail -20 "$work/log"; echo "run $run failed"; exit 1; }
  read -r wall memory < <(tail -1 "$work/time")
  walls+=("$wall")
  last=$(tail -1 "$work/out/convergence.csv")
  header=$(head -1 "$work/out/convergence.csv")
  echo "run $run: wall $wall s, peak $memory KB; last level: $(paste -d= \
    <(tr , '\n' <<< "$header") <(tr , '\n' <<< "$last") | sed -n 2,9p |
    tr '\n' ' ')"
done
median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{w[NR] = $1}
  END {print (NR % 2 ? w[(NR + 1) / 2] : (w[NR / 2] + w[NR / 2 + 1]) / 2)}')
echo "median wall $median s; load after: $(cut -d' ' -f1-3 /proc/loadavg)"
