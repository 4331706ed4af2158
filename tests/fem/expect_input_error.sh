#!/bin/bash
# usage: expect_input_error.sh SOFTCHAIN FILE.prm REGEX
# Passes if `softchain solve FILE.prm` exits with status 1 (bad input), its
# output matches REGEX (the message names the parameter or file) and carries
# no deal.II stack trace (a message for users, not developers).
softchain=$1 prm=$2 regex=$3
output=$("$softchain" solve "$prm" 2>&1)
status=$?
echo "$output"
if [ "$status" -ne 1 ]; then
  echo "expected exit status 1, got $status"
  exit 1
fi
if ! grep -Eq -- "$regex" <<<"$output"; then
  echo "the message does not match: $regex"
  exit 1
fi
if grep -q "Stacktrace" <<<"$output"; then
  echo "the message carries a stack trace"
  exit 1
fi
