#!/usr/bin/env bash
# Runs COMMAND, which must fail: exits 0 only when COMMAND exits non-zero
# and its output (stdout and stderr, lines joined by spaces, so that a
# message wrapped by deal.II still matches) matches the extended REGEX.
#
# usage: expect_failure.sh REGEX COMMAND [ARGUMENT ...]
set -uo pipefail
regex=$1
shift
output=$("$@" 2>&1)
status=$?
if [ $status -eq 0 ]; then
  echo "$output"
  echo "expect_failure: <$*> succeeded, but it must fail."
  exit 1
fi
if ! tr -s ' \n' '  ' <<< "$output" | grep -Eq -- "$regex"; then
  echo "$output"
  echo "expect_failure: <$*> failed (status $status), but its output does not match <$regex>."
  exit 1
fi
echo "expect_failure: <$*> failed as expected (status $status): <$regex> found."
