#!/usr/bin/env bash
# The mutation study of issue 7: breaks the code on purpose, once per
# mutation, and records which tests fail. Each mutation is a small change
# that alters the result; a suite whose checks bite fails on each.
#
#   gradient   ∇^K scaled by 1 + 1e-9 (LocalReconstruction)
#   bubble     the bubble dropped from the jump [[u]]_σ
#   friction   F dropped from the Coulomb slip projection (g = λ_n)
#   normal     n^+ flipped in the jump of fracture face 0
#
# Works on a copy of HEAD in WORKDIR (default /tmp/polyfrac-mutations), so
# the checkout is left alone; prints a markdown table. Takes about 4
# minutes per mutation on 2 cores after one full build.
#
# usage: scripts/mutation_study.sh [WORKDIR] [MUTATION ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-/tmp/polyfrac-mutations}
shift || true
mutations=("${@:-gradient bubble friction normal}")
read -r -a mutations <<< "${mutations[*]}"

rm -rf "$work/src"
mkdir -p "$work/src"
git -C "$root" archive HEAD | tar -x -C "$work/src"
ln -sfn "$root/../shared" "$work/shared"

# file and perl substitution of each mutation
declare -A file expression
file[gradient]=source/discretization/local_reconstruction.cc
expression[gradient]='s/(value_weights\.push_back\(0\.\);\n      \}\n)/$1    for (auto &g : gradient_coefficients)\n      g *= 1 + 1e-9;\n/'
file[bubble]=source/discretization/local_reconstruction.cc
expression[bubble]='s/\n    result\.emplace_back\(dofs\.n_node_sides\(\) \+ i, 1\.\);//'
file[friction]=source/contact/contact_mechanics.cc
expression[friction]='s/friction_coefficient \* std::max\(b_n, 0\.\)/std::max(b_n, 0.)/; s/-friction_coefficient \* hat\[d\]/-hat[d]/; s/-friction_coefficient \* b \* hat\[d\]/-b * hat[d]/'
file[normal]=source/discretization/local_reconstruction.cc
expression[normal]='s/(result\.emplace_back\(dofs\.n_node_sides\(\) \+ i, 1\.\);\n)/$1    if (i == 0)\n      for (auto &entry : result)\n        entry.second = -entry.second;\n/'

cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release > "$work/cmake.log"
cmake --build "$work/build" -j "$(nproc)" > "$work/build.log"

# A failing test is marked (check) when its program stopped (a check of
# the test itself: an assertion, a convergence check, a comparison), and
# (diff) when it ran through and only numdiff found its output changed.
classify() {
  local test=$1 dir
  dir=$work/build/tests/${test%.*}.${test##*.}
  if [ -d "$dir" ] && [ -f "$dir/failing_diff" ]; then
    echo "${test%.release} (diff)"
  else
    echo "${test%.release} (check)"
  fi
}

echo "| mutation | tests that fail |"
echo "|---|---|"
for m in "${mutations[@]}"; do
  f=$work/src/${file[$m]}
  cp "$f" "$f.orig"
  perl -0pi -e "${expression[$m]}" "$f"
  if cmp -s "$f" "$f.orig"; then
    echo "mutation $m did not apply to ${file[$m]}" >&2
    exit 1
  fi
  cmake --build "$work/build" -j "$(nproc)" > "$work/build-$m.log" 2>&1
  find "$work/build/tests" -name 'failing_*' -delete
  (cd "$work/build" && ctest -j "$(nproc)" > "$work/ctest-$m.log" 2>&1) || true
  failed=$(sed -n '/The following tests FAILED/,$p' "$work/ctest-$m.log" |
             grep -oP '^\s*\d+ - \K\S+' |
             while read -r t; do classify "$t"; done | paste -sd, - |
             sed 's/,/, /g')
  echo "| $m | ${failed:-none} |"
  # Restored with a new time stamp, so that the next build recompiles it.
  mv "$f.orig" "$f"
  touch "$f"
done
cmake --build "$work/build" -j "$(nproc)" > "$work/build-restored.log"
