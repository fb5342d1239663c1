#!/bin/sh
# install_test.sh CMAKE BUILD_DIR CXX GENERATOR: installs the build into a fresh
# prefix outside the build tree, then
#  1. builds tests/install_consumer against it (find_package(afford 0.11))
#     and runs it on the installed data ($AFFORD_DATA_DIR): it must print
#     the nutcracker's lever, the paper's pinch, hold and crash and the
#     root of its MuJoCo scene (afford::mjcf);
#     and its stepping example afford_step (docs/libraries.md);
#  2. builds every installed header with only its own library linked;
#  3. runs the installed afford from another folder without
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
for f in bin/afford include/afford/model/model.h include/afford/base/data_dir.h include/afford/guides/guides.h \
         include/afford/devices/scripted_agent.h \
         include/afford/render/image.h include/afford/gap/diagnose.h include/afford/explore/explore.h \
         include/afford/mjcf/mjcf_scene.h share/afford/rules/functions.yaml \
         share/afford/objects/nutcracker.yaml share/afford/devices/glove.yaml \
         lib/cmake/afford/afford-config.cmake lib/cmake/afford/afford-config-version.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done

# Each library's headers, all of them in one file, build with that one
# target linked: the folder a header is installed in names what it needs.
checks="$prefix/headers-check"
mkdir -p "$checks"
{
  echo "cmake_minimum_required(VERSION 3.25)"
  echo "project(afford_headers LANGUAGES CXX)"
  echo "find_package(afford 0.11 REQUIRED)"
} >"$checks/CMakeLists.txt"
for library in base load model rules guides session devices render gap explore mjcf; do
  for h in "$prefix/include/afford/$library"/*.h; do
    echo "#include <afford/$library/$(basename "$h")>"
  done >"$checks/$library.cpp"
  echo "int main() { return 0; }" >>"$checks/$library.cpp"
  {
    echo "add_executable(headers_$library $library.cpp)"
    echo "target_compile_features(headers_$library PRIVATE cxx_std_20)"
    echo "target_link_libraries(headers_$library PRIVATE afford::$library)"
  } >>"$checks/CMakeLists.txt"
done
"$cmake" -S "$checks" -B "$checks/build" -G "$generator" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
         -DCMAKE_PREFIX_PATH="$prefix" >"$checks/build.log" 2>&1 &&
  "$cmake" --build "$checks/build" >>"$checks/build.log" 2>&1 ||
  { cat "$checks/build.log"; fail "a library's headers do not build with its own target alone"; }

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
expect '^mjcf: <mujoco model="paper-nutcracker">$' "$out"
# Headers grouped by library: nothing flat in include/afford/, and the test
# harness's header is not installed.
[ -z "$(find "$prefix/include/afford" -maxdepth 1 -type f)" ] || fail "headers installed flat in include/afford/"
[ ! -e "$prefix/include/afford/mjcf/mujoco_harness.h" ] || fail "the MuJoCo harness header is installed"

# The stepping example (docs/libraries.md): with the script's own thumb it
# infers what run_session() inferred, at the same times.
ran=$(printf '%s\n' "$out" | grep -E "^[a-z]+ at [0-9.]+ s$")
stepped=$(cd / && AFFORD_DATA_DIR="$prefix/share/afford" "$prefix/consumer-build/afford_step" \
          sessions/paper-nutcracker.yaml 0 2>&1) || { echo "$stepped"; fail "afford_step failed"; }
echo "$stepped"
[ "$(printf '%s\n' "$stepped" | grep -E "^[a-z]+ at [0-9.]+ s$")" = "$ran" ] ||
  fail "afford_step with the script's thumb does not infer what the run did"
expect "^4000 frames, largest force on the actee [0-9.]+ N$" "$stepped"
# The thumb held 5 cm away from the arm, outward, never grasps: nothing inferred.
offside=$(cd / && AFFORD_DATA_DIR="$prefix/share/afford" "$prefix/consumer-build/afford_step" \
          sessions/paper-nutcracker.yaml -50 2>&1) || { echo "$offside"; fail "afford_step failed"; }
echo "$offside"
expect "^4000 frames, largest force on the actee 0\.0 N$" "$offside"
printf '%s\n' "$offside" | grep -qE " at [0-9.]+ s$" && fail "afford_step inferred a function with the thumb off the tool"

# The Python package (when the build has it): installed under the prefix's
# lib/python3.X/*-packages, importable from there with nothing but the path.
if ls "$build"/python/afford/_afford*.so >/dev/null 2>&1; then
  package=$(ls -d "$prefix"/lib/python3*/*-packages/afford 2>/dev/null | head -n 1)
  [ -n "$package" ] && [ -f "$package/__init__.py" ] && [ -f "$package/__init__.pyi" ] ||
    fail "the Python package is not installed under $prefix/lib/python3.X"
  ls "$package"/_afford*.so >/dev/null 2>&1 || fail "the Python module is not installed in $package"
  py=$(cd / && PYTHONPATH=$(dirname "$package") AFFORD_DATA_DIR="$prefix/share/afford" /usr/bin/python3 -c \
       "import afford; print(' '.join(f['name'] for f in afford.load(afford.data_dir() + '/sessions/paper-nutcracker.yaml').run()['functions']))" 2>&1) ||
    { echo "$py"; fail "the installed Python package failed"; }
  expect "^pinch hold crash$" "$py"
fi

out=$(cd / && env -u AFFORD_DATA_DIR "$prefix/bin/afford" describe "$prefix/share/afford/objects/nutcracker.yaml" 2>&1) ||
  { echo "$out"; fail "the installed afford failed"; }
echo "$out"
expect "^lever: type2" "$out"
expect "^  walnut +fits from 55 mm to 75 mm" "$out"
echo "install_test.sh: ok"
