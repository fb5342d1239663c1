#!/bin/sh
# install_test.sh CMAKE BUILD_DIR CXX GENERATOR: installs the build into a fresh
# prefix outside the build tree, then
#  1. builds tests/install_consumer against it (find_package(afford 0.10))
#     and runs it on the installed data ($AFFORD_DATA_DIR): it must print
#     the nutcracker's lever and the paper's pinch, hold and crash;
#  2. runs the installed afford from another folder without
#     $AFFORD_DATA_DIR: it must find the installed data beside itself
#     (the actees `describe` lists come from there).
set -eu
cmake=$1
build=$2
cxx=$3
generator=$4
here=$(cd "$(dirname "$0")" && pwd)
prefix=$(mktemp -d "${TMPDIR:-/tmp}/afford-install-XXXXXX")
trap 'rm -rf "$prefix"' EXIT

fail() {
  echo "install_test.sh: $*" >&2
  exit 1
}
# expect PATTERN TEXT: TEXT holds a line matching PATTERN (grep -E).
expect() {
  printf '%s\n' "$2" | grep -qE -- "$1" || fail "output does not match: $1"
}

"$cmake" --install "$build" --prefix "$prefix" >/dev/null
for f in bin/afford include/afford/model.h include/afford/data_dir.h share/afford/rules/functions.yaml \
         share/afford/objects/nutcracker.yaml share/afford/devices/glove.yaml \
         lib/cmake/afford/afford-config.cmake lib/cmake/afford/afford-config-version.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done

"$cmake" -S "$here" -B "$prefix/consumer-build" -G "$generator" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
         -DCMAKE_PREFIX_PATH="$prefix" >"$prefix/consumer-configure.log" 2>&1 ||
  { cat "$prefix/consumer-configure.log"; fail "the consumer does not configure"; }
"$cmake" --build "$prefix/consumer-build" >"$prefix/consumer-build.log" 2>&1 ||
  { cat "$prefix/consumer-build.log"; fail "the consumer does not build"; }

out=$(cd / && AFFORD_DATA_DIR="$prefix/share/afford" "$prefix/consumer-build/afford_consumer" \
      objects/nutcracker.yaml sessions/paper-nutcracker.yaml 2>&1) || { echo "$out"; fail "the consumer failed"; }
echo "$out"
expect "^nutcracker: type2, mechanical advantage 7\.20 \(effort at 0\.180 m, load at 0\.025 m\)$" "$out"
expect "^pinch at [0-9]+\.[0-9]{3} s$" "$out"
expect "^hold at [0-9]+\.[0-9]{3} s$" "$out"
expect "^crash at [0-9]+\.[0-9]{3} s$" "$out"

out=$(cd / && env -u AFFORD_DATA_DIR "$prefix/bin/afford" describe "$prefix/share/afford/objects/nutcracker.yaml" 2>&1) ||
  { echo "$out"; fail "the installed afford failed"; }
echo "$out"
expect "^lever: type2" "$out"
expect "^  walnut +fits from 55 mm to 75 mm" "$out"
echo "install_test.sh: ok"
