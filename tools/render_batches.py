#!/usr/bin/env python3
"""The batches section of docs/benchmarks.md (and the README's table) from one ctga_batch_bench run.

  render_batches.py BATCH_JSON PEAK_TXT    prints markdown on standard output

BATCH_JSON: ctga_batch_bench --benchmark_repetitions=N --benchmark_report_aggregates_only=true
--benchmark_out=… (medians read). PEAK_TXT: the line the benchmark prints first,
"fma peak: A Gflop/s scalar, B in 4 lanes, C in 8 lanes".
Rows batch_<algorithm>_<tree>/<scalar|pack4|pack8> give the time per robot (counter per_robot),
the speed-up of each width over the doubles, and for the arm the rate of Featherstone's minimal
operation count (counter gflops) against the FMA peak of that width; rows
batch_rollout_arm7/<width>[_threads] the time per robot-step (counter per_robot_step); rows
batch_bodies/<soa|pack2|pack4|pack8> the time per body-step (counter per_body_step).
"""
import json
import re
import sys

TARGET = 0.6  # issue 30: a width of L lanes at least 0.6 L times faster than the doubles
PEAK_SHARE_TARGET = 0.20  # the arm's RNEA in 8 lanes: at least 20 % of the 8-lane FMA peak


def medians(path):
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        out[b["run_name"].split("/iterations")[0]] = b
    return out


def fmt_ns(seconds):
    ns = seconds * 1e9
    return f"{ns / 1e3:.2f} µs" if ns >= 1e3 else f"{ns:.1f} ns"


def main():
    rows = medians(sys.argv[1])
    peak_line = open(sys.argv[2]).read()
    found = re.search(r"([\d.]+) Gflop/s scalar, ([\d.]+) in 4 lanes, ([\d.]+) in 8 lanes", peak_line)
    peak = dict(zip(["scalar", "pack4", "pack8"], map(float, found.groups())))
    lines = ["## Batches: many robots per instruction stream",
             "",
             "`ctga_batch_bench` (`bench/chains_batch*.cpp`, built with `-march=native`): RNEA, ABA and CRBA",
             "over 512 robots kept as an array of structures, in doubles robot by robot and with",
             "`ctga::pack<double, 4 | 8>` as the scalar (chains/batch.hpp's `load` and `store` included).",
             f"This core's FMA peak, measured by the benchmark: {peak['scalar']:.1f} Gflop/s in doubles,",
             f"{peak['pack4']:.1f} in 4 lanes, {peak['pack8']:.1f} in 8 lanes. Rate: Featherstone's",
             "operation count for an n-joint revolute chain (Table 10.1) per second, the arm only;",
             f"✓/✗: a speed-up of at least {TARGET} × lanes; the arm's RNEA in 8 lanes at least",
             f"{PEAK_SHARE_TARGET:.0%} of the 8-lane peak.",
             "",
             "| algorithm | tree | doubles | 4 lanes | 8 lanes | 4 lanes: speed-up | 8 lanes: speed-up | 8 lanes: rate | of 8-lane peak |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for tree in ["arm7", "tree"]:
        for alg in ["rnea", "aba", "crba"]:
            name = f"batch_{alg}_{tree}"
            t = {w: rows.get(f"{name}/{w}", {}).get("per_robot") for w in ["scalar", "pack4", "pack8"]}
            if None in t.values():
                continue
            s4, s8 = t["scalar"] / t["pack4"], t["scalar"] / t["pack8"]
            mark = lambda s, lanes: f"{s:.2f} {'✓' if s >= TARGET * lanes else '✗'}"
            rate = share = "—"
            g = rows[f"{name}/pack8"].get("gflops")
            if g is not None:
                rate = f"{g / 1e9 if g > 1e6 else g:.1f} Gflop/s"
                gv = g / 1e9 if g > 1e6 else g
                share = f"{gv / peak['pack8']:.0%}" + (f" {'✓' if gv / peak['pack8'] >= PEAK_SHARE_TARGET else '✗'}" if alg == "rnea" else "")
            lines.append(f"| {alg} | {tree} | {fmt_ns(t['scalar'])} | {fmt_ns(t['pack4'])} | {fmt_ns(t['pack8'])} | "
                         f"{mark(s4, 4)} | {mark(s8, 8)} | {rate} | {share} |")
    lines += ["",
              "Rollouts: 1,024 arms × 1,000 steps of `lie_rk4` (four ABA evaluations a step), time per",
              "robot-step (`chains::for_each_pack`; all cores: one contiguous run of packs per thread).",
              "",
              "| rollout | doubles | 4 lanes | 8 lanes | 8 lanes: speed-up |",
              "| --- | --- | --- | --- | --- |"]
    for suffix, label in [("", "one core"), ("_threads", "all cores")]:
        t = {w: rows.get(f"batch_rollout_arm7/{w}{suffix}", {}).get("per_robot_step") for w in ["scalar", "pack4", "pack8"]}
        if None in t.values():
            continue
        base = rows["batch_rollout_arm7/scalar"]["per_robot_step"]
        threads = int(rows[f"batch_rollout_arm7/pack8{suffix}"].get("threads", 1))
        lines.append(f"| {label} ({threads} thread{'s' if threads > 1 else ''}) | {fmt_ns(t['scalar'])} | {fmt_ns(t['pack4'])} | "
                     f"{fmt_ns(t['pack8'])} | {base / t['pack8']:.2f} (against doubles on one core) |")
    t = {w: rows.get(f"batch_bodies/{w}", {}).get("per_body_step") for w in ["soa", "pack2", "pack4", "pack8"]}
    if None not in t.values():
        lines += ["",
                  "Single bodies: 10,000 free bodies (diagonal inertia) stepped by `rk4` with renormalisation:",
                  "`scenes/batch.hpp` (structure of arrays, stepped in packs of this build's width, 8 lanes) and",
                  "hand-made packs of bodies (`rk4{}.step` on `body_motion<pack<double, L>>`, one array of states",
                  "per pack), time per body-step:",
                  "",
                  "| scenes/batch.hpp | packs of 2 | packs of 4 | packs of 8 | packs of 8 / batch |",
                  "| --- | --- | --- | --- | --- |",
                  f"| {fmt_ns(t['soa'])} | {fmt_ns(t['pack2'])} | {fmt_ns(t['pack4'])} | {fmt_ns(t['pack8'])} | {t['pack8'] / t['soa']:.2f} |"]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
