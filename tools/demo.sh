#!/usr/bin/env bash
# Install missing Debian packages, build and run the demo (examples/demo.cpp).
# BUILD_DIR overrides the build tree (default build/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
export BUILD_DIR=${BUILD_DIR:-$root/build}

if [[ ! -f examples/demo.cpp ]]; then
    echo "demo: examples/demo.cpp does not exist yet" >&2
    exit 1
fi
bash tools/deps.sh
bash tools/configure.sh
cmake --build "$BUILD_DIR" --target demo -j"$(nproc)"
"$BUILD_DIR/examples/demo"
