#!/usr/bin/env bash
# Install missing Debian packages, build everything and run all tests.
# BUILD_DIR overrides the build tree (default build/); arguments go to ctest
# (e.g. bash tools/test.sh -L unit, bash tools/test.sh -R dense).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
export BUILD_DIR=${BUILD_DIR:-$root/build}
jobs=$(nproc)

bash tools/deps.sh
bash tools/configure.sh
cmake --build "$BUILD_DIR" -j"$jobs"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$jobs" "$@"
