#!/usr/bin/env bash
# Checks that the module dependencies of PolyFrac point one way:
#   base -> mesh -> fractures -> dofs -> discretization -> physics -> contact
#   -> postprocessing/io -> app
# A header or source of a module may include headers of its own module and of
# earlier modules only. Prints every offending include and exits non-zero if
# there is one. Usage: check_include_order.sh [repository root]
set -euo pipefail
root="${1:-$(dirname "$0")/..}"

declare -A rank=(
  [base]=0 [mesh]=1 [fractures]=2 [dofs]=3 [discretization]=4 [physics]=5
  [contact]=6 [postprocessing]=7 [io]=7 [app]=8)

status=0
for dir in "$root/include/polyfrac" "$root/source"; do
  for module_dir in "$dir"/*/; do
    module=$(basename "$module_dir")
    if [ -z "${rank[$module]+x}" ]; then
      echo "$module_dir: unknown module '$module' (add it to the order in $0)"
      status=1
      continue
    fi
    while IFS=: read -r file line text; do
      included=$(sed -E 's|.*polyfrac/([a-z_]+)/.*|\1|' <<< "$text")
      if [ -z "${rank[$included]+x}" ]; then
        echo "$file:$line: includes unknown module '$included'"
        status=1
      elif [ "${rank[$included]}" -gt "${rank[$module]}" ]; then
        echo "$file:$line: module '$module' includes later module '$included'"
        status=1
      fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]polyfrac/' \
               "$module_dir" || true)
  done
done

if [ $status -eq 0 ]; then
  echo "Include order OK: base -> mesh -> fractures -> dofs -> discretization -> physics -> contact -> postprocessing/io -> app"
fi
exit $status
