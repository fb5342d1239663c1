#!/bin/sh
# outputs_test.sh AFFORD SOURCE_DIR CASE: nothing a user wrote is
# overwritten, and every limit agrees with itself (issue 31,
# engine/base/output_file.h). Each CASE is one ctest test; every one works in a
# fresh folder and checks the exit status, the message and the files left.
afford=$1
src=$2
case=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$src" || exit 1
session=sessions/paper-nutcracker.yaml

fail() { echo "outputs_test $case: $*"; [ -f "$work/log" ] && cat "$work/log"; exit 1; }
# expect STATUS PATTERN COMMAND...: the exit status and a line of stdout+stderr.
expect() {
  want=$1 pattern=$2
  shift 2
  "$@" > "$work/log" 2>&1
  got=$?
  [ "$got" -eq "$want" ] || fail "exit status $got, expected $want: $*"
  grep -qE -- "$pattern" "$work/log" || fail "no line matches '$pattern': $*"
}
# A session file beside the work, naming the shipped files by absolute path.
session_file() {  # FILE TIMESTEP SECONDS
  cat > "$1" <<EOS
session: limits
description: the nutcracker held still
object: $src/objects/nutcracker.yaml
actee: {file: $src/actees/walnut.yaml, at: 60 mm}
agent: $src/agents/hand.yaml
rules: $src/rules/functions.yaml
grasps: $src/rules/grasps.yaml
timestep: $2
script:
  - t: 0 s
    hand: {position: [80 mm, 40 mm, 190 mm]}
    grip: {thumb: 160 mm, index: 160 mm, squeeze: 0 mm}
    posture: medium_wrap
  - t: $3
    grip: {thumb: 160 mm, index: 160 mm, squeeze: 0 mm}
EOS
}

case $case in
  input_as_output)
    session_file "$work/s.yaml" "1 ms" "0.1 s"
    before=$(cksum < "$work/s.yaml")
    expect 1 "s.yaml: one of this command's inputs; choose another output" \
      "$afford" run "$work/s.yaml" --out "$work/o" --record "$work/s.yaml" --force
    expect 1 "s.yaml: one of this command's inputs" "$afford" export --mjcf "$work/s.yaml" --out "$work/s.yaml" --force
    [ "$(cksum < "$work/s.yaml")" = "$before" ] || fail "the session was changed"
    ;;
  symlink)
    mkdir "$work/o"
    echo "keep me" > "$work/precious"
    ln -s "$work/precious" "$work/o/trace.csv"
    expect 1 "o/trace.csv: a symbolic link; afford does not write through links" \
      "$afford" run $session --out "$work/o" --force
    [ "$(cat "$work/precious")" = "keep me" ] || fail "the link's target was written"
    [ -L "$work/o/trace.csv" ] || fail "the link was replaced"
    ;;
  foreign_file)
    echo "my notes" > "$work/notes.afrec"
    expect 1 "notes.afrec: exists and afford did not write it; choose another name, or --force to replace it" \
      "$afford" run $session --out "$work/o" --record "$work/notes.afrec"
    [ "$(cat "$work/notes.afrec")" = "my notes" ] || fail "the foreign file was replaced"
    expect 0 "^recorded 4000 frames to" "$afford" run $session --out "$work/o" --record "$work/notes.afrec" --force
    expect 0 "4000 frames, ended cleanly" "$afford" replay "$work/notes.afrec"
    ;;
  schema_force)
    # Every command that writes files takes --force, as the refusal says.
    mkdir "$work/s"
    echo "my schema" > "$work/s/object.schema.json"
    expect 1 "object.schema.json: exists and afford did not write it; choose another name, or --force to replace it" \
      "$afford" schema object --out "$work/s"
    [ "$(cat "$work/s/object.schema.json")" = "my schema" ] || fail "the foreign file was replaced"
    "$afford" schema object --out "$work/s" --force || fail "schema --force failed"
    grep -q '"title": "afford object file"' "$work/s/object.schema.json" || fail "--force wrote no schema"
    "$afford" live --help | grep -q -- "--force" || fail "afford live has no --force"
    ;;
  mp4)
    # ffmpeg's MP4 is an output like the others: a foreign one is refused
    # before any frame is drawn; afford's own is replaced, no temporary left.
    mkdir "$work/o"
    echo "my film" > "$work/o/session.mp4"
    expect 1 "session.mp4: exists and afford did not write it" \
      "$afford" render $session --out "$work/o" --fps 5 --size 160x120
    [ "$(cat "$work/o/session.mp4")" = "my film" ] || fail "the foreign MP4 was replaced"
    [ -z "$(ls "$work/o" | grep frame_)" ] || fail "frames were drawn before the refusal"
    expect 0 "session.mp4" "$afford" render $session --out "$work/o" --fps 5 --size 160x120 --force
    expect 0 "session.mp4" "$afford" render $session --out "$work/o" --fps 5 --size 160x120
    [ "$(head -c 8 "$work/o/session.mp4" | tail -c 4)" = "ftyp" ] || fail "session.mp4 is not an MP4"
    [ -z "$(ls -A "$work/o" | grep '^\.session')" ] || fail "a temporary file was left: $(ls -A "$work/o")"
    ;;
  rerun_same_folder)
    # afford's own files are replaced without --force; no temporary file is left.
    expect 0 "^wrote .*trace.csv" "$afford" run $session --out "$work/o" --record "$work/r.afrec"
    expect 0 "^wrote .*trace.csv" "$afford" run $session --out "$work/o" --record "$work/r.afrec"
    [ "$(ls -A "$work/o" | tr '\n' ' ')" = ".afford-outputs timeline.jsonl trace.csv " ] || fail "left: $(ls -A "$work/o")"
    ;;
  timestep_10us)
    session_file "$work/s.yaml" "10 us" "0.01 s"
    expect 0 "s.yaml: ok" "$afford" check "$work/s.yaml"
    session_file "$work/s.yaml" "9 us" "0.01 s"
    expect 1 "s.yaml:8:11: expected a timestep from" "$afford" check "$work/s.yaml"
    ;;
  record_cap)
    # 600 s at 0.1 ms: 6 million frames, over 2 GiB: refused before the run.
    session_file "$work/s.yaml" "0.1 ms" "600 s"
    expect 1 "long.afrec: cannot record 6000000 frames of 0.1 ms: at least 2[0-9.]+ MiB .* over the 1024.0 MiB a recording may hold \\(replay reads no more\\)" \
      "$afford" run "$work/s.yaml" --out "$work/o" --record "$work/long.afrec"
    [ ! -e "$work/long.afrec" ] || fail "a recording was started"
    ;;
  trailing_bytes)
    expect 0 "^recorded" "$afford" run $session --out "$work/o" --record "$work/r.afrec"
    printf 'extra' >> "$work/r.afrec"
    expect 0 "4000 frames, ended cleanly; 5 bytes after its end record are ignored" "$afford" replay "$work/r.afrec"
    ;;
  progress_not_a_terminal)
    # 1.2 million frames, about a second: announced, then a line every 0.05 s instead of every 5 s.
    session_file "$work/s.yaml" "0.5 ms" "600 s"
    AFFORD_PROGRESS_SECONDS=0.05 "$afford" run "$work/s.yaml" --out "$work/o" > "$work/out" 2> "$work/log" ||
      fail "run failed"
    grep -q "^run: 1200000 frames of 0.0005 s to simulate; progress below$" "$work/log" || fail "not announced"
    grep -qE "^frame [0-9]+/1200000, [0-9.]+ frames/s, [0-9.]+ s left$" "$work/log" || fail "no progress line on stderr"
    grep -q "frames/s" "$work/out" && fail "progress on stdout"
    grep -q "$(printf '\033')" "$work/log" && fail "terminal codes in a log"
    ;;
  stale_maps)
    args="objects/nutcracker.yaml --placements 1 --thumbs 1 --efforts 2 --grasps medium_wrap --out $work/e"
    expect 0 "^wrote" "$afford" explore $args --actees actees/walnut.yaml actees/hazelnut.yaml
    [ -f "$work/e/maps/hazelnut.svg" ] || fail "no hazelnut map: $(ls "$work/e/maps")"
    echo "mine" > "$work/e/maps/notes.txt"
    expect 0 "^wrote" "$afford" explore $args --actees actees/walnut.yaml
    [ -f "$work/e/maps/walnut.svg" ] || fail "no walnut map"
    [ ! -e "$work/e/maps/hazelnut.svg" ] && [ ! -e "$work/e/maps/hazelnut.png" ] || fail "a stale map is left"
    [ "$(cat "$work/e/maps/notes.txt")" = "mine" ] || fail "a user's file was removed"
    ;;
  gap_rows)
    # One row over the limit of 1000000: refused with the reason, before the fit.
    awk 'BEGIN { print "t,angle,effort_force,actee_force";
                 for (i = 0; i < 1000001; i++) printf "%.3f,%.9f,%.6f,0\n", i * 1e-3, 0.3 + 0.1 * sin(i * 0.00628), 1 + 0.1 * cos(i * 0.00628) }' \
      > "$work/trace.csv"
    printf 'measurement: long\nobject: %s/objects/nutcracker.yaml\neffort_at: 160 mm\ntrace: trace.csv\n' "$src" > "$work/m.yaml"
    expect 1 "m.yaml: 1000001 rows in its traces, more than the 1000000 a diagnosis takes \\(its fit grows faster than the rows" \
      "$afford" gap "$work/m.yaml"
    ;;
  model_out)
    # afford model --out: never over its input, a foreign file only with --force.
    model="model tests/data/urdf/two-arms/mobility.urdf --mass 100 --application 60,90 --emphasis 0,20"
    expect 1 "mobility.urdf: one of this command's inputs" "$afford" $model --out tests/data/urdf/two-arms/mobility.urdf --force
    mesh=tests/data/urdf/two-arms/textured_objs/fixed-arm.obj  # a mesh the URDF names is an input too
    before=$(cksum < $mesh)
    expect 1 "fixed-arm.obj: one of this command's inputs" "$afford" $model --out $mesh --force
    [ "$(cksum < $mesh)" = "$before" ] || fail "the URDF's mesh was changed"
    echo "mine" > "$work/o.yaml"
    expect 1 "o.yaml: exists and afford did not write it" "$afford" $model --out "$work/o.yaml"
    [ "$(cat "$work/o.yaml")" = "mine" ] || fail "the foreign file was replaced"
    expect 0 "^wrote .*o.yaml" "$afford" $model --out "$work/o.yaml" --force
    expect 0 "^wrote .*o.yaml" "$afford" $model --out "$work/o.yaml"
    ;;
  *) fail "no such case" ;;
esac
echo "outputs_test $case: ok"
