#!/usr/bin/env bash
# The integrators' accuracy report:
#   bash tools/accuracy.sh
# builds ctga_accuracy and the integrator tests (Release), runs the work–precision sweep (every
# integrator × ctga, 6×6 matrix and dense representations × body and fixed frame), the energy
# history and the far-from-origin curve, quotes the stress tests' printed figures and ABA's on an
# ill-conditioned robot (aba_accuracy_test), and renders
# docs/accuracy.md with docs/img/{work_precision,energy_history,far_from_origin}.svg.
# BUILD_DIR overrides the build tree (default build/). Takes a few minutes (the dense runs).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
export BUILD_DIR=${BUILD_DIR:-$root/build}

bash tools/deps.sh python3-matplotlib
bash tools/configure.sh
cmake --build "$BUILD_DIR" --target ctga_accuracy integrators_test integrator_stress_test aba_accuracy_test -j"$(nproc)"
out=$BUILD_DIR/accuracy
mkdir -p "$out" docs/img
"$BUILD_DIR/bench/ctga_accuracy" "$out" | tee "$out/sweep.log"
{ "$BUILD_DIR/tests/integrators_test"; "$BUILD_DIR/tests/integrator_stress_test"; } >"$out/stress.log"
"$BUILD_DIR/tests/aba_accuracy_test" >"$out/aba.log"  # ABA on an ill-conditioned robot against long double
/usr/bin/python3 tools/render_accuracy.py "$out" "$out/stress.log" docs/accuracy.md docs/img
echo "accuracy: wrote docs/accuracy.md and docs/img/{work_precision,energy_history,far_from_origin}.svg"
