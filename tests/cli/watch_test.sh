#!/bin/sh
# watch_test.sh AFFORD SOURCE_DIR: `afford run --watch` re-runs when a file
# the session uses is edited, with no rebuild: raising the walnut's limit
# tenfold takes the crash away; a broken edit prints its error and keeps the
# last good model; fixing it runs again; renaming a function in the function
# models changes the verdict's name. Every wait is bounded.
afford=$1
src=$2
work=$(mktemp -d)
trap 'kill $pid 2>/dev/null; rm -rf "$work"' EXIT
cp -r "$src/objects" "$src/actees" "$src/agents" "$src/rules" "$src/sessions" "$work/"
cd "$work" || exit 1

: > log
"$afford" run sessions/paper-nutcracker.yaml --watch --runs 5 --out out >> log 2>&1 &
pid=$!

# wait_for COUNT PATTERN: until the log has COUNT lines matching PATTERN.
wait_for() {
  i=0
  while [ "$(grep -cE -- "$2" log)" -lt "$1" ]; do  # grep -c prints 0 on no match
    i=$((i + 1))
    if [ $i -gt 300 ]; then
      echo "watch_test: timed out waiting for $1 x '$2'"; cat log; exit 1
    fi
    sleep 0.1
  done
}

wait_for 1 "watching"
grep -q "^crash at" log || { echo "watch_test: no crash at first"; cat log; exit 1; }

sed -i 's/^limit: 378 N/limit: 3780 N/' actees/walnut.yaml      # the walnut is now too hard
wait_for 2 "watching"
[ "$(grep -c '^crash at' log)" -eq 1 ] || { echo "watch_test: still crashed"; cat log; exit 1; }

sed -i 's/^limit: 3780 N/limit: oops/' actees/walnut.yaml         # a broken edit
wait_for 1 "keeping the last good model"
grep -qE "walnut.yaml:[0-9]+:8: expected a force" log || { echo "watch_test: no located error"; cat log; exit 1; }

sed -i 's/^limit: oops/limit: 378 N/' actees/walnut.yaml          # fixed: crash again
wait_for 4 "watching"
[ "$(grep -c '^crash at' log)" -eq 2 ] || { echo "watch_test: no crash after the fix"; cat log; exit 1; }

sed -i 's/- name: crash/- name: crack/; s/carry, crash]/carry, crack]/' rules/functions.yaml  # a function renamed, in its strength too
wait
grep -q '^crack at' log || { echo "watch_test: the edited function model was not used"; cat log; exit 1; }
cat log
echo "watch_test: ok"
