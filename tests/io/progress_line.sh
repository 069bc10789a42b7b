#!/usr/bin/env bash
# The status line of long steps (base/progress_line.h): on a terminal (a
# pseudo-terminal made by script(1)) the user guide's 2D scene shows the run
# state and each Newton iteration, and erases the status before every line
# of its own output; through a pipe (as in a log or a test) nothing of it is
# written.
# usage: progress_line.sh POLYFRAC SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
run=("$program" "$source/prm/user-guide-2d.prm" --set "Time/End time=3"
     --set "Output/Write VTU=false" --set "Output/Output directory=$work/out")

printf -v command '%q ' "${run[@]}"
script -qec "$command" "$work/terminal.txt" > /dev/null
# The typescript holds what the terminal got: CR returns to the start of
# the status, ESC [ K erases the rest of the line.
for expected in "Newton iteration 1, relative increment" \
  "step 2, t = 1 -> 2 of 3; " "s in this step"; do
  grep -qF -- "$expected" "$work/terminal.txt" ||
    { echo "FAILED: the terminal shows no <$expected>"; exit 1; }
done
# Every line the program prints starts on an erased line: the status before
# "Step to t = 2" is erased first.
grep -qF -- $'\r\033[KStep to t = 2' "$work/terminal.txt" ||
  { echo "FAILED: the status is not erased before the step line"; exit 1; }
echo "terminal: run state, Newton iterations, erased before each step line"

"${run[@]}" > "$work/pipe.txt" 2>&1
if grep -q -e "Newton iteration 1," -e $'\033' -e $'\r' "$work/pipe.txt"; then
  echo "FAILED: the status line was written to a pipe"; exit 1
fi
echo "pipe: no status line"
