#!/usr/bin/env bash
# Installs every Debian package the build and the tests need, then builds.
# Run as root on Debian 12. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config ninja-build
  libeigen3-dev libfcl-dev libccd-dev libyaml-cpp-dev
  libglm-dev libosmesa6-dev zlib1g-dev libdeflate-dev libusb-1.0-0-dev umockdev libumockdev-dev
  libgtest-dev libgmock-dev libbenchmark-dev libmujoco-dev libode-dev
  libcli11-dev help2man
  libcivetweb-dev libjs-three libassimp-dev liburdfdom-dev
  nlohmann-json3-dev python3-jsonschema python3-yaml parallel
  clang-14 libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-venv
  chromium
)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DAFFORD_WERROR=ON -DAFFORD_UNITY=ON
cmake --build build
# Install (default prefix /usr/local): the program, the libraries, the
# shipped data and the Python package, where Debian's /usr/bin/python3
# finds it from any folder with no environment variable (docs/python.md).
cmake --install build >/dev/null
(cd / && /usr/bin/python3 -c "import afford")
