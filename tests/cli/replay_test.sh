#!/bin/sh
# replay_test.sh AFFORD SOURCE_DIR HELPER: `afford run --record` then `afford
# replay`: the recording replays to the same events; it replays the recorded
# model files, not the edited ones on disk; under edited function models
# (hold's `for` raised from 300 ms to 500 ms) it prints the difference of the
# timelines; a file that is not a recording, or of another version, is an
# error naming it; a recording whose events were changed (by HELPER
# --tamper, checksums made good) replays to a difference at that frame.
afford=$1
src=$2
helper=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$src/objects" "$src/actees" "$src/agents" "$src/rules" "$src/sessions" "$work/"
cd "$work" || exit 1

fail() {
  echo "replay_test: $1"; [ -f log ] && cat log; exit 1
}

"$afford" run sessions/paper-nutcracker.yaml --out out --record nut.afrec > log 2>&1 || fail "run --record failed"
grep -q "^recorded 4000 frames to nut.afrec$" log || fail "no 'recorded' line"
grep -q "^hold at" log || fail "no hold in the recorded run"
grep "^[a-z]* at [0-9.]* s$" log > run_verdicts

# Bit for bit, after the walnut on disk was made ten times harder: the
# recorded copy is replayed, and the changed file is noted.
sed -i 's/^limit: 378 N/limit: 3780 N/' actees/walnut.yaml
"$afford" replay nut.afrec > log 2>&1 || fail "replay failed"
grep -q "^recording nut.afrec: session paper-nutcracker (script sessions/paper-nutcracker.yaml), 4000 frames, ended cleanly$" log ||
  fail "no recording summary"
grep -q "^note: actees/walnut.yaml has changed since the recording" log || fail "no note of the changed walnut"
grep -q "^replayed 4000 frames: events identical to the recording, and the final state$" log || fail "not identical"
grep "^[a-z]* at [0-9.]* s$" log > replay_verdicts
cmp -s run_verdicts replay_verdicts || fail "the replay's verdicts differ from the run's"

# --out: the same timeline and trace, byte for byte, as the run wrote.
"$afford" replay nut.afrec --out replayed > log 2>&1 || fail "replay --out failed"
cmp -s out/trace.csv replayed/trace.csv || fail "replay --out: trace.csv differs from the run's"
cmp -s out/timeline.jsonl replayed/timeline.jsonl || fail "replay --out: timeline.jsonl differs from the run's"

"$afford" replay nut.afrec --json > log 2>&1 || fail "replay --json failed"
grep -q '^{"recording":"nut.afrec","session":"paper-nutcracker","frames":4000,"tail":"end","changed_since":\["actees/walnut.yaml"\],"identical":true,"functions":\[{"name":"pinch"' log ||
  fail "replay --json"

# Under edited rules: hold is inferred 200 ms later; nothing else moves.
sed 's/^        for: 300 ms$/        for: 500 ms/' rules/functions.yaml > hold500.yaml
cmp -s rules/functions.yaml hold500.yaml && fail "the edit of hold's 'for' did not apply"
"$afford" replay nut.afrec --rules hold500.yaml > log 2>&1 || fail "replay --rules failed"
grep -q "^timeline difference, recorded (-) vs re-run (+):$" log || fail "no diff heading"
grep -qE "^- [0-9]+\.[0-9]{3} s  hold inferred$" log || fail "no '- ... hold inferred'"
grep -qE "^\+ [0-9]+\.[0-9]{3} s  hold inferred  \(\+0\.200 s\)$" log || fail "no '+ ... hold inferred (+0.200 s)'"
grep -q "crash inferred" log && fail "crash should not move"
grep -qE "^[0-9]+ events the same, [1-9][0-9]* shifted, 0 only in the recording, 0 only in the re-run$" log ||
  fail "no diff summary"

# The unchanged rules give no difference.
"$afford" replay nut.afrec --rules rules/functions.yaml > log 2>&1 || fail "replay --rules (same) failed"
grep -qE "^the timelines are identical \([0-9]+ events\)$" log || fail "same rules: not identical"

# A broken rules file is reported at its line.
sed 's/^        for: 300 ms$/        for: 300 parsecs/' rules/functions.yaml > broken.yaml
"$afford" replay nut.afrec --rules broken.yaml > log 2>&1 && fail "broken rules accepted"
grep -qE "^broken.yaml:[0-9]+:[0-9]+: " log || fail "no located error for broken rules"

# Not a recording; another version; a missing file.
printf 'session: not a recording\n' > notrec.afrec
"$afford" replay notrec.afrec > log 2>&1; [ $? -eq 1 ] || fail "wrong magic: exit status"
grep -q "^afford: notrec.afrec: not an afford recording (its magic number is wrong)$" log || fail "wrong magic: message"
{ head -c 8 nut.afrec; printf '\011\000\000\000'; tail -c +13 nut.afrec; } > v9.afrec
"$afford" replay v9.afrec > log 2>&1; [ $? -eq 1 ] || fail "wrong version: exit status"
grep -q "^afford: v9.afrec: recording format version 9; this afford reads version 1$" log || fail "wrong version: message"
"$afford" replay nowhere.afrec > log 2>&1; [ $? -eq 1 ] || fail "missing file: exit status"
grep -q "nowhere.afrec" log || fail "missing file: message"

# Cut in the middle of a frame: replays the frames before it.
head -c 500000 nut.afrec > cut.afrec
"$afford" replay cut.afrec > log 2>&1 || fail "cut: replay failed"
grep -qE "^recording cut.afrec: .*, [0-9]+ frames; the last record was incomplete \(" log || fail "cut: no summary"
grep -qE "^replayed [0-9]+ frames: events identical to the recording$" log || fail "cut: not identical"
"$afford" replay > log 2>&1; [ $? -eq 2 ] || fail "no argument: exit status"

# A recorded event moved by 1 ms: the replay names the frame, exit status 1.
frame=$("$helper" --tamper nut.afrec tampered.afrec | sed -n 's/^tampered with frame \([0-9]*\)$/\1/p')
[ -n "$frame" ] || fail "tamper failed"
"$afford" replay tampered.afrec > log 2>&1; [ $? -eq 1 ] || fail "tampered: exit status"
grep -qE "^replayed 4000 frames: frame $frame \(t = [0-9.]+ s\) differs$" log || fail "tampered: no first differing frame"
grep -qE "^  recorded: .* at [0-9.]+ s" log || fail "tampered: no recorded events"
grep -qE "^  replayed: .* at [0-9.]+ s" log || fail "tampered: no replayed events"
echo "replay_test: ok"
