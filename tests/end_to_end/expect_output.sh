#!/bin/bash
# usage: expect_output.sh STATUS REGEX COMMAND [ARGS...]
# Passes if COMMAND exits with STATUS and its output (stdout and stderr)
# matches the extended regular expression REGEX. ctest's
# PASS_REGULAR_EXPRESSION alone would ignore the exit status.
expected=$1 regex=$2
shift 2
output=$("$@" 2>&1)
status=$?
echo "$output"
if [ "$status" -ne "$expected" ]; then
  echo "expected exit status $expected, got $status"
  exit 1
fi
if ! grep -Ezq -- "$regex" <<<"$output"; then
  echo "the output does not match: $regex"
  exit 1
fi
