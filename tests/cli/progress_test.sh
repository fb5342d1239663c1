#!/bin/sh
# progress_test.sh AFFORD OUT: `afford render` shows its progress on a
# terminal (script(1) gives it one); in a pipe or a log only plain lines,
# every few seconds (cli/progress.h), never the terminal's redrawn bar.
afford=$1
out=$2
args="render sessions/paper-nutcracker.yaml --out $out --fps 5 --size 160x120"
tty=$(script -qec "$afford $args" /dev/null) || { echo "render on a terminal failed: $tty"; exit 1; }
if ! printf '%s\n' "$tty" | grep -qE 'frame [0-9]+/[0-9]+, [0-9.]+ frames/s, [0-9.]+ s left'; then
  echo "no progress on a terminal:"; printf '%s\n' "$tty"; exit 1
fi
piped=$($afford $args 2>&1) || { echo "render in a pipe failed: $piped"; exit 1; }
if printf '%s\n' "$piped" | grep -q "$(printf '\033')"; then
  echo "terminal codes written to a pipe:"; printf '%s\n' "$piped"; exit 1
fi
