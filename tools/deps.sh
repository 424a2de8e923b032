#!/usr/bin/env bash
# Install the Debian packages ctga's build needs, only those missing.
#   bash tools/deps.sh                 (tools/demo.sh and tools/test.sh call it; clang is for
#                                      tools/test.sh's second build tree, Debian 12's clang 14;
#                                      python3 runs tools/urdf_to_ctga.py for the tests)
#   bash tools/deps.sh extra-pkg ...   the same, plus these (tools/bench.sh: valgrind, matplotlib,
#                                      libmujoco-dev for ctga_chains_bench's MuJoCo rows)
# CTGA_SKIP_DEPS=1 skips the check (e.g. on non-Debian systems).
set -euo pipefail

packages=(g++ clang cmake ninja-build libboost-dev catch2 libbenchmark-dev libeigen3-dev time python3 "$@")

if [[ "${CTGA_SKIP_DEPS:-0}" == 1 ]]; then
    exit 0
fi
if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "deps: dpkg-query not found (not Debian?); install by hand: ${packages[*]}" >&2
    exit 0
fi

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == *" ok installed" ]] || missing+=("$p")
done
(( ${#missing[@]} == 0 )) && exit 0

sudo=()
if (( EUID != 0 )); then
    if command -v sudo >/dev/null 2>&1; then
        sudo=(sudo)
    else
        echo "deps: missing packages: ${missing[*]}; run as root or install sudo" >&2
        exit 1
    fi
fi

echo "deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
