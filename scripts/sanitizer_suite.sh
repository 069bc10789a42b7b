#!/usr/bin/env bash
# The Debug + AddressSanitizer/UndefinedBehaviorSanitizer suite (README:
# "Debug and sanitizer suite"): configures PolyFrac in Debug against deal.II's
# debug library with POLYFRAC_SANITIZE=ON in build-debug/, builds it and runs
# every test except the long program tests listed below. The sanitizer
# options and suppressions come with the tests (tests/sanitizers/).
set -euo pipefail
cd "$(dirname "$0")/.."

# Program tests left out: their Debug + sanitizer run time (2 cores) is given
# next to each; the Release suite runs them.
long_tests=(
)

cmake -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug -DPOLYFRAC_SANITIZE=ON \
  > build-debug.log 2>&1 || { cat build-debug.log; exit 1; }
cmake --build build-debug -j "$(nproc)" >> build-debug.log 2>&1 ||
  { tail -50 build-debug.log; exit 1; }
echo "Built build-debug/ (log: build-debug.log)"

exclude="^($(IFS='|'; echo "${long_tests[*]}"))\.debug$"
cd build-debug
ctest -j "$(nproc)" --output-on-failure -E "$exclude"
