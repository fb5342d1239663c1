#!/bin/sh
# explore_shards_test.sh AFFORD WORKDIR: a grid run whole, and the same grid
# in three shards run side by side under GNU parallel (as on a cluster) and
# joined with --merge, write the same files byte for byte.
set -u
afford=$1
work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
grid="objects/nutcracker.yaml --actees actees/walnut.yaml actees/peanut.yaml actees/egg.yaml
      --placements 2 --thumbs 2 --efforts 3 --grasps medium_wrap,tip_pinch"
# shellcheck disable=SC2086
"$afford" explore $grid --threads 2 --out "$work/whole" >/dev/null || { echo "explore_shards: the whole run failed" >&2; exit 1; }
# shellcheck disable=SC2086
parallel --will-cite --halt now,fail=1 "$afford" explore $grid --threads 1 --shard {}/3 --out "$work/shard{}" ::: 1 2 3 >/dev/null ||
  { echo "explore_shards: a shard failed" >&2; exit 1; }
"$afford" explore --merge "$work/shard1" "$work/shard2" "$work/shard3" --out "$work/merged" >/dev/null ||
  { echo "explore_shards: the merge failed" >&2; exit 1; }
diff -r "$work/whole" "$work/merged" || { echo "explore_shards: the merge differs from the whole run" >&2; exit 1; }
# Every file a whole run writes is there.
for f in points.csv thresholds.csv summary.txt explore.json maps/walnut.svg maps/walnut.png; do
  [ -s "$work/merged/$f" ] || { echo "explore_shards: $f is missing" >&2; exit 1; }
done
# A shard left out is an error that says so.
"$afford" explore --merge "$work/shard1" "$work/shard3" --out "$work/partial" 2>"$work/err" && {
  echo "explore_shards: a merge with a shard missing succeeded" >&2; exit 1; }
grep -q "a part is missing" "$work/err" || { cat "$work/err" >&2; exit 1; }
rm -rf "$work"
