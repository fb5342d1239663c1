#!/bin/sh
# expect.sh STATUS PATTERN COMMAND...: runs COMMAND and passes when it exits
# with STATUS and its output (stdout and stderr) contains PATTERN (grep -E).
want_status=$1
pattern=$2
shift 2
out=$("$@" 2>&1)
status=$?
printf '%s\n' "$out"
if [ "$status" -ne "$want_status" ]; then
  echo "expect.sh: exit status $status, expected $want_status" >&2
  exit 1
fi
if ! printf '%s\n' "$out" | grep -qE -- "$pattern"; then
  echo "expect.sh: output does not match: $pattern" >&2
  exit 1
fi
