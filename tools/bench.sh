#!/usr/bin/env bash
# The benchmark suite, its instruction counts and its report:
#   bash tools/bench.sh
# builds ctga_bench (Release), runs every <operation>/<implementation> 7 times (medians; the
# repetitions of all benchmarks interleaved at random, so that a noisy spell of a shared machine
# does not land on one benchmark), counts the instructions of one call of each ctga, spatial
# and Eigen kernel with callgrind, and renders docs/benchmarks.md with docs/img/benchmarks.svg.
# The compile-time tables come from tools/compile-cost.sh when it has been run (its fragment in
# $BUILD_DIR/bench/).
# The collision layer's queries beside FCL and Bullet come from ctga_collision_bench (collision.json).
# BUILD_DIR overrides the build tree (default build/). Run it on a quiet machine.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
export BUILD_DIR=${BUILD_DIR:-$root/build}

bash tools/deps.sh valgrind python3-matplotlib libmujoco-dev libfcl-dev libbullet-dev libode-dev libdart-dev
bash tools/configure.sh -DCTGA_BUILD_BENCHMARKS=ON
cmake --build "$BUILD_DIR" --target ctga_bench -j"$(nproc)"
out=$BUILD_DIR/bench
mkdir -p "$out" docs/img

"$out/ctga_bench" --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true --benchmark_min_time=0.2 \
    --benchmark_out="$out/results.json" --benchmark_out_format=json

# instructions of one call: callgrind counts inside the kernel only (--toggle-collect)
operations=(momentum energy bracket coadjoint motor_product screw_transform coscrew_transform inertia_transform eom step)
calls=1000
: >"$out/instructions.txt"
for op in "${operations[@]}"; do
    for impl in ctga spatial eigen; do
        total=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null \
            --toggle-collect="bench::$op(bench::${impl}_inputs const&)" \
            "$out/ctga_bench" --repeat "$op/$impl" "$calls" 2>&1 | awk '/Collected/ {print $4}')
        echo "$op $impl $((total / calls))" >>"$out/instructions.txt"
    done
done

# kinematic trees: ctga_chains_bench, its instructions, and the scaling executables (1–64 bodies)
cmake --build "$BUILD_DIR" --target ctga_chains_bench ctga_chains_flops ctga_chains_scaling_small ctga_chains_scaling_32 \
    ctga_chains_scaling_64 -j"$(nproc)"
"$out/ctga_chains_flops" >"$out/chains_flops.tsv"  # operation counts and the scalar peak (render_benchmarks.py)
"$out/ctga_chains_bench" --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true --benchmark_min_time=0.2 \
    --benchmark_out="$out/chains.json" --benchmark_out_format=json
: >"$out/chains_instructions.txt"
for tree in arm7 chain30 tree quadruped humanoid; do
    algorithms=(rnea aba crba)
    [[ $tree == quadruped ]] || algorithms+=(fk)
    [[ $tree == arm7 || $tree == tree ]] && algorithms+=(jacobian)  # the trees with a Jacobian row
    for a in "${algorithms[@]}"; do
        impls=(ctga spatial)
        grep -q "\"${a}_$tree/mujoco\"" "$out/chains.json" && impls+=(mujoco)  # (built with MuJoCo)
        for impl in "${impls[@]}"; do
            total=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='*chain_kernel*' \
                "$out/ctga_chains_bench" --repeat "${a}_$tree/$impl" "$calls" 2>&1 | awk '/Collected/ {print $4}')
            echo "${a}_$tree $impl $((total / calls))" >>"$out/chains_instructions.txt"
        done
    done
done
scaling=()
for group in small 32 64; do
    "$out/ctga_chains_scaling_$group" --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
        --benchmark_min_time=0.1 --benchmark_out="$out/chains_scaling_$group.json" --benchmark_out_format=json
    scaling+=("$out/chains_scaling_$group.json")
done

# many robots at once: ctga_batch_bench (-march=native), its first line the FMA peak per width
cmake --build "$BUILD_DIR" --target ctga_batch_bench -j"$(nproc)"
"$out/ctga_batch_bench" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out/batch.json" --benchmark_out_format=json >"$out/batch.txt"
head -n 1 "$out/batch.txt" >"$out/batch_peak.txt"

# collision: ctga_collision_bench, the narrowphase pairs and the broadphase beside FCL and Bullet
# (each found by CMake; tools/deps.sh installs both); render_benchmarks.py reads collision.json
# beside results.json (the pairs' table, with their max_err counters)
cmake --build "$BUILD_DIR" --target ctga_collision_bench -j"$(nproc)"
"$out/ctga_collision_bench" --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
    --benchmark_min_time=0.2 --benchmark_out="$out/collision.json" --benchmark_out_format=json

# scenes with contact: ctga_contact_bench beside Bullet and MuJoCo (contact.json; one run each:
# a scene is minutes of steps, its counters the figures)
cmake --build "$BUILD_DIR" --target ctga_contact_bench -j"$(nproc)"
"$out/ctga_contact_bench" --benchmark_out="$out/contact.json" --benchmark_out_format=json

/usr/bin/python3 tools/render_benchmarks.py "$out/results.json" "$out/instructions.txt" \
    "$out/compile_cost.md" docs/benchmarks.md docs/img/benchmarks.svg \
    "$out/chains.json" "$out/chains_instructions.txt" docs/img/chains_scaling.svg "${scaling[@]}"
{ echo; /usr/bin/python3 tools/render_batches.py "$out/batch.json" "$out/batch_peak.txt"; } >>docs/benchmarks.md
echo "bench: wrote docs/benchmarks.md and docs/img/benchmarks.svg"
