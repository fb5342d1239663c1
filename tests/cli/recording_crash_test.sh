#!/bin/sh
# recording_crash_test.sh AFFORD HELPER SOURCE_DIR: a crash in the middle of
# a recording loses at most the frame being written. HELPER records
# sessions/paper-nutcracker.yaml slowly (1 ms of sleep per frame); once
# about 1300 frames are on disk (past pinch and hold) it is killed with
# SIGKILL, and `afford replay` of what it left must replay every frame
# written, with the events identical to the recording, and the verdicts of
# an uninterrupted run up to there. Every wait is bounded.
afford=$1
helper=$2
src=$3
work=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -9 $pid 2>/dev/null; rm -rf "$work"' EXIT
cd "$src" || exit 1

"$helper" sessions/paper-nutcracker.yaml "$work/crash.afrec" 1000 > "$work/helper.log" 2>&1 &
pid=$!

# Wait until the file holds the header and about 1300 frames (371 bytes each).
i=0
while :; do
  size=$(stat -c %s "$work/crash.afrec" 2>/dev/null || echo 0)
  [ "$size" -gt 500000 ] && break
  i=$((i + 1))
  if [ $i -gt 600 ]; then
    echo "recording_crash_test: the recording did not grow"; cat "$work/helper.log"; exit 1
  fi
  sleep 0.05
done
kill -9 $pid
wait $pid 2>/dev/null
pid=
if grep -q "^recorded" "$work/helper.log"; then
  echo "recording_crash_test: the helper finished before it was killed"; exit 1
fi

"$afford" replay "$work/crash.afrec" > "$work/replay.log" 2>&1
status=$?
cat "$work/replay.log"
[ $status -eq 0 ] || { echo "recording_crash_test: replay exit status $status"; exit 1; }
# The header line says how the file ends: no end record, or a last record cut short.
grep -qE "^recording .*crash.afrec: session paper-nutcracker .*, [0-9]+ frames; (the session did not end cleanly|the last record was incomplete)" \
  "$work/replay.log" || { echo "recording_crash_test: no summary of the cut recording"; exit 1; }
frames=$(sed -n 's/^replayed \([0-9]*\) frames: events identical to the recording$/\1/p' "$work/replay.log")
[ -n "$frames" ] || { echo "recording_crash_test: the replay did not match the recording"; exit 1; }
if [ "$frames" -lt 1200 ] || [ "$frames" -ge 4000 ]; then
  echo "recording_crash_test: replayed $frames frames, expected at least 1200 and fewer than 4000"; exit 1
fi
# The verdicts up to the cut are those of a whole run.
"$afford" run sessions/paper-nutcracker.yaml --out "$work/out" > "$work/run.log" 2>&1 || { echo "recording_crash_test: run failed"; exit 1; }
awk -v end="$frames" '/^[a-z]+ at [0-9.]+ s$/ && $3 * 1000 <= end' "$work/run.log" > "$work/expected"
grep -E '^[a-z]+ at [0-9.]+ s$' "$work/replay.log" > "$work/got"
grep -q "^hold at" "$work/expected" || { echo "recording_crash_test: no hold before the cut"; exit 1; }
cmp -s "$work/expected" "$work/got" || { echo "recording_crash_test: verdicts differ from a whole run's"; cat "$work/expected"; exit 1; }
echo "recording_crash_test: ok ($frames frames survived kill -9)"
