#!/usr/bin/env bash
# Configure the build tree (BUILD_DIR, default build/): Ninja when available, Release.
# Used by tools/demo.sh and tools/test.sh; extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}

args=(-S "$root" -B "$build")
# the generator can only be chosen on the first configure of a build tree
if [[ ! -f "$build/CMakeCache.txt" && -z "${CMAKE_GENERATOR:-}" ]] && command -v ninja >/dev/null 2>&1; then
    args+=(-G Ninja)
fi
# Release on the first configure (or $CMAKE_BUILD_TYPE); later runs keep the cached type
if [[ -n "${CMAKE_BUILD_TYPE:-}" ]]; then
    args+=(-DCMAKE_BUILD_TYPE="$CMAKE_BUILD_TYPE")
elif [[ ! -f "$build/CMakeCache.txt" ]]; then
    args+=(-DCMAKE_BUILD_TYPE=Release)
fi
cmake "${args[@]}" "$@"
