#!/usr/bin/env bash
# Speed, memory and accuracy of the elasticity solve on meshes of growing
# size: the B2 scenes (prm/b2-2d.prm, prm/b2-3d.prm: exact traction
# prescribed, Model = elasticity) on 2D quadrilaterals and triangles and 3D
# hexahedra and tetrahedra, each with Linear solver/Method = direct (UMFPACK)
# and AMG (CG + ML with the rigid-body modes). Every case runs R times
# (default 3); the table gives medians, so speed and accuracy are read
# together:
#
#   dim cells n_cells n_dofs solver asm_s solve_s cells/s CG peak_MB err_grad_u
#
# n_dofs are the unknowns of the linear system (Dirichlet dofs excluded), as
# in convergence.csv; asm_s and solve_s come from the rows assembly and
# solve of the program's timing table (solve_s includes the AMG setup);
# cells/s is n_cells over asm_s; peak_MB is the maximum resident set size
# from /usr/bin/time -v.
# The default set takes about 9 minutes on 2 cores, --quick under one.
#
# usage: benchmarks/run_benchmarks.sh [--quick] [--repeats R] [--keep]
#                                     [path/to/polyfrac]
#   path/to/polyfrac  the built program (default: build/polyfrac)
#   --quick           small meshes only
#   --repeats R       runs per case (default 3)
#   --keep            keep the generated parameter files and logs
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

program=$root/build/polyfrac
quick=false
repeats=3
keep=false
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=true ;;
    --repeats) repeats=$2; shift ;;
    --keep) keep=true ;;
    -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "unknown option $1 (see --help)" >&2; exit 2 ;;
    *) program=$1 ;;
  esac
  shift
done

if [ ! -x "$program" ]; then
  echo "no program at $program: build it (cmake -DCMAKE_BUILD_TYPE=Release;" \
       "make polyfrac-bin) or pass its path" >&2
  exit 1
fi
program=$(cd "$(dirname "$program")" && pwd)/$(basename "$program")
if ! /usr/bin/time -v true > /dev/null 2>&1; then
  echo "GNU time is needed for the peak memory: apt-get install time" >&2
  exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/polyfrac-bench.XXXXXX")
if $keep; then
  echo "parameter files and logs: $work" >&2
else
  trap 'rm -rf "$work"' EXIT
fi

# Cases: dim, cell type, subdivisions per direction, solvers. UMFPACK is
# left out where its fill-in alone would take minutes (3D hexahedra at 32:
# about 3 minutes and 3 GB a run on 2 cores).
if $quick; then
  cases=("2 hypercube 64 direct AMG"
         "2 hypercube 128 direct AMG"
         "2 simplex 64 direct AMG"
         "3 hypercube 8 direct AMG"
         "3 hypercube 16 direct AMG"
         "3 simplex 8 direct AMG")
else
  cases=("2 hypercube 64 direct AMG"
         "2 hypercube 128 direct AMG"
         "2 hypercube 256 direct AMG"
         "2 hypercube 512 direct AMG"
         "2 simplex 64 direct AMG"
         "2 simplex 128 direct AMG"
         "2 simplex 256 direct AMG"
         "2 simplex 512 direct AMG"
         "3 hypercube 8 direct AMG"
         "3 hypercube 16 direct AMG"
         "3 hypercube 24 direct AMG"
         "3 hypercube 32 AMG"
         "3 hypercube 40 AMG"
         "3 simplex 8 direct AMG"
         "3 simplex 16 direct AMG"
         "3 simplex 24 direct AMG"
         "3 simplex 32 direct AMG")
fi

# write_prm DIM CELL_TYPE N METHOD OUTPUT_DIRECTORY: the B2 scene of the
# source tree on an N^dim box, one level.
write_prm() {
  local subdivisions=$3
  for ((d = 1; d < $1; ++d)); do subdivisions="$subdivisions, $3"; done
  cat <<EOF
include $root/prm/b2-${1}d.prm
subsection Mesh
  set Subdivisions = $subdivisions
  set Cell type = $2
  set Global refinements = 0
end
subsection Convergence study
  set Number of refinement levels = 1
end
subsection Linear solver
  set Method = $4
end
subsection Output
  set Output directory = $5
  set Print timings = true
  set Write VTU = false
end
EOF
}

# median: of the numbers on standard input.
median() {
  sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# field LOG SECTION: the wall time of SECTION in the program's timing table
# (deal.II's TimerOutput: "| SECTION | calls | 1.23s | 45% |").
field() {
  sed -n "s/^| $2 *| *[0-9]* | *\([0-9.eE+-]*\)s |.*/\1/p" "$1"
}

echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores" \
     "($(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1))," \
     "load $(cut -d' ' -f1-3 /proc/loadavg), $repeats runs per case"
printf "%-3s %-9s %8s %8s %-6s %8s %8s %9s %4s %8s %11s\n" \
  dim cells n_cells n_dofs solver asm_s solve_s cells/s CG peak_MB err_grad_u
for case in "${cases[@]}"; do
  read -r dim cell_type n methods <<< "$case"
  for method in $methods; do
    name=${dim}d-$cell_type-$n-$method
    write_prm "$dim" "$cell_type" "$n" "$method" "$work/$name" > "$work/$name.prm"
    : > "$work/$name.times"
    failed=false
    for ((r = 1; r <= repeats; ++r)); do
      echo "running $name ($r/$repeats)" >&2
      log=$work/$name.$r.log
      if ! /usr/bin/time -v -o "$work/$name.$r.time" \
             "$program" "$work/$name.prm" > "$log" 2>&1; then
        echo "$name failed, see $log:" >&2
        tail -5 "$log" >&2
        failed=true
        break
      fi
      echo "$(field "$log" assembly) $(field "$log" solve)" \
           "$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/$name.$r.time")" \
           >> "$work/$name.times"
    done
    $failed && continue

    # level,h,n_cells,n_dofs,err_u,err_grad_u,...: the one level.
    IFS=, read -r _ _ n_cells n_dofs _ err_grad_u _ < <(sed -n 2p "$work/$name/convergence.csv")
    assembly=$(cut -d' ' -f1 "$work/$name.times" | median)
    solve=$(cut -d' ' -f2 "$work/$name.times" | median)
    peak_kb=$(cut -d' ' -f3 "$work/$name.times" | median)
    iterations=$(sed -n 's/^CG iterations: //p' "$work/$name.1.log")
    printf "%-3s %-9s %8s %8s %-6s %8.3f %8.3f %9.0f %4s %8.0f %11.4e\n" \
      "$dim" "$cell_type" "$n_cells" "$n_dofs" "$method" "$assembly" "$solve" \
      "$(awk "BEGIN { print $n_cells / $assembly }")" "${iterations:--}" \
      "$(awk "BEGIN { print $peak_kb / 1024 }")" "$err_grad_u"
  done
done
