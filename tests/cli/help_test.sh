#!/bin/sh
# help_test.sh AFFORD: `afford COMMAND --help` exits 0 for every command
# `afford --help` lists, and names every option of that command with a
# description. The options come from the program (its completion script,
# made from the same declarations as the help), not from a copy here; the
# commands and options named below are those users rely on, so that one
# dropped or renamed by mistake fails too.
afford=$1
fail=0
commands=$("$afford" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }')
[ -n "$commands" ] || { echo "help_test: afford --help lists no commands" >&2; exit 1; }
for c in check describe explore gap render guide rules run live replay test export completion; do
  echo "$commands" | grep -qx "$c" || { echo "help_test: afford --help does not list $c" >&2; fail=1; }
done
script=$("$afford" completion bash) || { echo "help_test: afford completion bash failed" >&2; exit 1; }
for c in $commands; do
  help=$("$afford" "$c" --help)
  status=$?
  if [ $status -ne 0 ]; then
    echo "help_test: afford $c --help exited $status" >&2
    fail=1
    continue
  fi
  # The options the completion offers for this command.
  options=$(printf '%s\n' "$script" | awk -v c="    $c)" '
    $0 == c { on = 1; next }
    on && /compgen -W "-/ { sub(/.*compgen -W "/, ""); sub(/".*/, ""); print; exit }')
  [ -n "$options" ] || { echo "help_test: no options for $c in the completion" >&2; fail=1; }
  for o in $options; do
    # "  --out DIR     description", or the description on the next line.
    described=$(printf '%s\n' "$help" | awk -v o="$o" '
      want { print ($0 ~ /^      +[^ -]/ ? "yes" : "no"); exit }
      { n = split($0, w, /[ ,]+/) }
      $0 ~ /^  -/ {
        for (i = 1; i <= n; i++) if (w[i] == o) {
          rest = $0; sub(/^  [^ ]+( [^ ]+)*  +/, "", rest)
          if (rest != $0 && rest != "") { print "yes"; exit }
          want = 1
        }
      }')
    if [ "$described" != yes ]; then
      echo "help_test: afford $c --help does not describe $o" >&2
      fail=1
    fi
  done
done
# Options that exist since before the declarations and must keep their names.
expect_options() {
  c=$1
  shift
  for o in "$@"; do
    "$afford" "$c" --help | grep -qE -- "^  $o( |$)" || { echo "help_test: afford $c has no $o" >&2; fail=1; }
  done
}
expect_options run --json --out --record --watch --runs
expect_options live --device --duration --wait --silence --record --out
expect_options replay --rules --json --out
expect_options render --out --fps --size --guides --no-frames
expect_options guide --actees --guides --json
expect_options describe --actees --effects
expect_options gap --json --effects --write-patch --probe
expect_options rules --list
expect_options test --coverage
exit $fail
