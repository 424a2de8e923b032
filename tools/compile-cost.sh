#!/usr/bin/env bash
# Compile-time cost of ctga: wall time, CPU time and peak memory (/usr/bin/time -v) of
#   (a) bench/compile/core_only.cpp   the algebra core and the engine only: one motor product
#   (b) bench/compile/mechanics.cpp   <ctga/ctga.hpp> and the mechanics (momentum, transforms
#                                     by a motor_map, acceleration, body_frame_rates)
#   (b2) bench/compile/arm7_dynamics.cpp  a 7-dof arm's RNEA, ABA and CRBA (ctga::chains)
#   (b3) bench/compile/eom_jacobian.cpp   the exact Jacobian ∂ṡ/∂s of one body's equations of motion
#   (b4) bench/compile/quadruped_frames.cpp  a quadruped from URDF (tests/data/legged.urdf, merged,
#                                     26 frames): RNEA, ABA, CRBA, four feet's frame Jacobians; at
#                                     -O2; (b5) the same with J̇, the centre of mass and the
#                                     centroidal momentum matrix
#   (b6) bench/compile/arm7_derivatives.cpp  the arm's rnea_derivatives and aba_derivatives (with
#                                     minverse), at -O2
#   (b7) bench/compile/collision_all.cpp  every collision shape kind and every pair a scene can
#                                     meet (separation, contact, bounds, ray casts), at -O2
#   (b8) bench/contact.cpp            the scenes with contact (physics_world of cubes and of jointed
#                                     spheres, the pinch), without the peers' rows, at -O2
#   (b9) bench/contact_pile.cpp       the mixed pile (a world of four body kinds: spheres, capsules,
#                                     boxes, hulls), without the peers' rows, at -O2
#   (c) the heaviest test unit         only with --with-heaviest (about 30 s)
#   (e) bench/compile/tree_dynamics.cpp  one tree's RNEA, ABA and CRBA at -O2 against its number of
#                                     bodies: serial chains of 8, 16, 32 and 64 bodies, the 39-body
#                                     humanoid, and the arm (arm7_dynamics.cpp); a plot of seconds
#                                     against bodies (docs/img/compile_trees.svg)
#   (f) with --robots DIR: every DIR/*.urdf as it comes (tools/urdf_to_ctga.py, default options, and
#                                     again with --floating-base), its RNEA, ABA and CRBA in one unit at
#                                     -O2 (tree_dynamics.cpp -DCTGA_ROBOT); a table of seconds and MB
#   (d) bench/compile/generators.cpp   one algebra of n generators and one geometric product of
#                                     two general vectors, bivectors, even elements and general
#                                     multivectors, n = 3..10 (past the loop threshold: looped)
# one compile at a time, each with the compiler and flags of the configured build (the compile
# command of an example in $BUILD_DIR/compile_commands.json, default build/), the object going
# to /dev/null. Writes the Markdown tables to $BUILD_DIR/bench/compile_cost.md, the data to
# $BUILD_DIR/bench/compile_cost.tsv and a plot to docs/img/compile_cost.svg.
#
#   bash tools/compile-cost.sh [--with-heaviest] [--heaviest tests/FILE.cpp] [--repeat K]
#                              [--nmin 3] [--nmax 10] [--plot FILE.svg | --no-plot]
#                              [--cxxflags 'FLAGS'] [--robots DIR]
#
#   --repeat K   compile each unit K times and keep the fastest (default 1); the table also shows
#                CPU time and the load average, so a measurement slowed by other work shows up
#                as wall ≫ cpu or a high load.
#   --cxxflags   extra flags after the build's own, for every measured compile (an A/B of a
#                header change: -include a file that redefines a macro; another -O level).
#
# Needs a configured build tree (bash tools/configure.sh) and /usr/bin/time. Run it on an
# otherwise idle machine: do not build at the same time.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
db=$build/compile_commands.json
# shellcheck source=lib/compile-db.sh
source "$root/tools/lib/compile-db.sh"

with_heaviest=0
heaviest=parts/body_kinds_test_part1.cpp  # the heaviest unit measured (test files compile in parts)
repeat=1
nmin=3 nmax=10
plot=$root/docs/img/compile_cost.svg
extra=
robots=
while (($#)); do
    case $1 in
        --with-heaviest) with_heaviest=1 ;;
        --heaviest) heaviest=$2; with_heaviest=1; shift ;;
        --repeat) repeat=$2; shift ;;
        --nmin) nmin=$2; shift ;;
        --nmax) nmax=$2; shift ;;
        --plot) plot=$2; shift ;;
        --no-plot) plot= ;;
        --cxxflags) extra=$2; shift ;;
        --robots) robots=$2; shift ;;
        -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        *) echo "compile-cost: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
((nmin >= 1 && nmax <= 16 && nmin <= nmax)) || { echo "compile-cost: need 1 <= nmin <= nmax <= 16" >&2; exit 2; }

[[ -f "$db" ]] || { echo "compile-cost: $db not found; configure first (bash tools/configure.sh)" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "compile-cost: /usr/bin/time not found (apt-get install time)" >&2; exit 1; }

# ---- the reference compile command: an example's (ctga::ctga and the project's warnings) ----
compile_db_read "$db" '/examples/[^/]+\.cpp$'
if ((${#cdb_files[@]} == 0)); then compile_db_read "$db" '/bench/[^/]+\.cpp$'; fi
((${#cdb_files[@]} > 0)) || { echo "compile-cost: no example or benchmark in $db (configure with CTGA_BUILD_EXAMPLES=ON)" >&2; exit 1; }
ref_dir=${cdb_dirs[0]} ref_cmd=${cdb_cmds[0]} ref_file=${cdb_files[0]}
[[ $ref_cmd == *" -c $ref_file"* ]] || { echo "compile-cost: cannot find '-c $ref_file' in: $ref_cmd" >&2; exit 1; }
compiler=${ref_cmd%% *}
flags=$ref_cmd
flags=${flags#"$compiler "}
flags=${flags%" -c $ref_file"*}
flags=$(compile_db_to_devnull " $flags" | sed -E 's/ -o [^ ]+//')  # no object, no dependency files
[[ -z $extra ]] || flags="$flags $extra"

# measured: object to /dev/null
measure_cmd() { # SOURCE [EXTRA FLAGS...] -> the command
    local src=$1; shift
    printf '%s' "$compiler$flags $* -o /dev/null -c $src"
}
# not measured: an executable printing what the product is (blade counts, cost_of), at -O0
report_cmd() { # SOURCE EXE [EXTRA FLAGS...]
    local src=$1 exe=$2; shift 2
    printf '%s' "$compiler$flags $* -O0 -DCTGA_REPORT -o $exe $src"
}

load() { cut -d' ' -f1 /proc/loadavg; }

# measure DIR CMD: the fastest of $repeat compiles; sets m_wall m_cpu m_rss m_status m_load
measure() {
    local k
    m_wall= m_cpu= m_rss= m_status= m_load=
    for ((k = 0; k < repeat; ++k)); do
        local l
        l=$(load)
        time_compile "$1" "$2"
        if [[ -z $m_wall ]] || awk -v a="$time_wall" -v b="$m_wall" 'BEGIN { exit !(a < b) }'; then
            m_wall=$time_wall m_cpu=$time_cpu m_rss=$time_rss m_status=$time_status m_load=$l
        fi
    done
}

out=$build/bench
gen=$out/compile
mkdir -p "$out" "$gen"
md=$out/compile_cost.md
tsv=$out/compile_cost.tsv
start=$(date +%s)
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

# ---- (a)–(c) -----------------------------------------------------------------------------
units=()  # rows: label \t file \t wall \t cpu \t rss \t status \t load
measure_unit() { # LABEL FILE DIR CMD
    printf '  %-12s %s … ' "$1" "$2" >&2
    measure "$3" "$4"
    printf '%ss %sMB %s\n' "$m_wall" "$m_rss" "$m_status" >&2
    units+=("$1"$'\t'"$2"$'\t'"$m_wall"$'\t'"$m_cpu"$'\t'"$m_rss"$'\t'"$m_status"$'\t'"$m_load")
}
echo "compile-cost: translation units" >&2
measure_unit "(a) core" bench/compile/core_only.cpp "$ref_dir" "$(measure_cmd "$root/bench/compile/core_only.cpp")"
measure_unit "(b) mechanics" bench/compile/mechanics.cpp "$ref_dir" "$(measure_cmd "$root/bench/compile/mechanics.cpp")"
measure_unit "(b2) arm7 RNEA+ABA+CRBA" bench/compile/arm7_dynamics.cpp "$ref_dir" "$(measure_cmd "$root/bench/compile/arm7_dynamics.cpp")"
measure_unit "(b3) EOM Jacobian" bench/compile/eom_jacobian.cpp "$ref_dir" "$(measure_cmd "$root/bench/compile/eom_jacobian.cpp")"
python3 "$root/tools/urdf_to_ctga.py" "$root/tests/data/legged.urdf" --name legged --floating-base -o "$gen/legged.hpp"
measure_unit "(b4) quadruped + frames, -O2" bench/compile/quadruped_frames.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/compile/quadruped_frames.cpp" "-I$gen -O2")"
measure_unit "(b5) … + J̇, CoM, CMM, -O2" bench/compile/quadruped_frames.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/compile/quadruped_frames.cpp" "-I$gen -O2 -DCTGA_MORE")"
measure_unit "(b6) arm7 RNEA+ABA derivatives, -O2" bench/compile/arm7_derivatives.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/compile/arm7_derivatives.cpp" "-O2")"
measure_unit "(b7) collision: every shape kind and pair, -O2" bench/compile/collision_all.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/compile/collision_all.cpp" "-O2")"
measure_unit "(b8) scenes with contact (ctga_contact_bench without peers), -O2" bench/contact.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/contact.cpp" "-O2")"
measure_unit "(b9) the mixed pile (ctga_contact_bench without peers), -O2" bench/contact_pile.cpp "$ref_dir" \
    "$(measure_cmd "$root/bench/contact_pile.cpp" "-O2")"
if ((with_heaviest)); then
    compile_db_read "$db" "${heaviest//./\\.}\$"
    ((${#cdb_files[@]} == 1)) || { echo "compile-cost: $heaviest not in $db (configure with CTGA_BUILD_TESTS=ON)" >&2; exit 1; }
    hcmd=$(compile_db_to_devnull "${cdb_cmds[0]}")
    [[ -z $extra ]] || hcmd=${hcmd/" -o /dev/null"/" $extra -o /dev/null"}
    measure_unit "(c) heaviest" "$heaviest" "${cdb_dirs[0]}" "$hcmd"
fi

# ---- (e) trees against their bodies ------------------------------------------------------
echo "compile-cost: a tree's RNEA + ABA + CRBA against its bodies, -O2" >&2
ttsv=$out/compile_trees.tsv
printf 'tree\tbodies\tdofs\twall\tcpu\trss\tstatus\tload\n' > "$ttsv"
tree_unit() { # LABEL BODIES DOFS FILE FLAGS
    printf '  %-12s … ' "$1" >&2
    measure "$ref_dir" "$(measure_cmd "$root/$4" "$5")"
    printf '%ss %sMB %s\n' "$m_wall" "$m_rss" "$m_status" >&2
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$m_wall" "$m_cpu" "$m_rss" "$m_status" "$m_load" >> "$ttsv"
}
tree_unit "arm7" 7 7 bench/compile/arm7_dynamics.cpp "-O2"
for n in 8 16 32 64; do tree_unit "chain $n" "$n" "$n" bench/compile/tree_dynamics.cpp "-O2 -DCTGA_BODIES=$n"; done
tree_unit "humanoid" 39 44 bench/compile/tree_dynamics.cpp "-O2 -DCTGA_HUMANOID"

# ---- (f) real robots ----------------------------------------------------------------------
rtsv=$out/compile_robots.tsv
printf 'robot\toptions\tbodies\tdofs\twall\tcpu\trss\tstatus\tload\n' > "$rtsv"
if [[ -n $robots ]]; then
    echo "compile-cost: real robots' RNEA + ABA + CRBA, -O2" >&2
    for urdf in "$robots"/*.urdf; do
        for opt in "" --floating-base; do
            name=$(basename "$urdf" .urdf)
            hdr=$gen/robot_${name}${opt:+_floating}.hpp
            printf '  %-40s %-16s … ' "$name" "${opt:-(default)}" >&2
            if ! python3 "$root/tools/urdf_to_ctga.py" "$urdf" --name robot $opt -o "$hdr" 2>/dev/null; then
                echo "not converted" >&2
                continue
            fi
            # "// Robot "robot": B bodies, F frames, D degrees of freedom; …"
            read -r bodies dofs < <(sed -nE '2s/.*: ([0-9]+) bodies, [0-9]+ frames, ([0-9]+) degrees.*/\1 \2/p' "$hdr")
            measure "$ref_dir" "$(measure_cmd "$root/bench/compile/tree_dynamics.cpp" "-O2 -DCTGA_ROBOT=robot -include $hdr")"
            printf '%ss %sMB %s\n' "$m_wall" "$m_rss" "$m_status" >&2
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "${opt:-(default)}" "$bodies" "$dofs" "$m_wall" "$m_cpu" "$m_rss" \
                "$m_status" "$m_load" >> "$rtsv"
        done
    done
fi

# ---- (d) n generators --------------------------------------------------------------------
kinds=(vectors bivectors even general)
echo "compile-cost: one product against the number of generators" >&2
printf 'kind\tn\toperand_blades\tpairs\tresult_blades\tmul\tadd\twall\tcpu\trss\tstatus\tload\tnote\n' > "$tsv"
for p in 1 2 3 4; do
    kind=${kinds[p - 1]}
    for ((n = nmin; n <= nmax; ++n)); do
        printf '  %-9s n=%-2d … ' "$kind" "$n" >&2
        defs="-DCTGA_N=$n -DCTGA_PRODUCT=$p"
        measure "$ref_dir" "$(measure_cmd "$root/bench/compile/generators.cpp" "$defs")"
        exe=$gen/generators_${p}_$n
        note= ob= rb= mul= add=
        if [[ $m_status == ok ]]; then
            (cd "$ref_dir" && eval "$(report_cmd "$root/bench/compile/generators.cpp" "$exe" "$defs")") >/dev/null 2>&1 &&
                read -r ob rb mul add < <("$exe") || note="report build failed"
        else
            # why it failed: the first error of the compiler
            note=$(cd "$ref_dir" && eval "$(measure_cmd "$root/bench/compile/generators.cpp" "$defs")" 2>&1 |
                       grep -m1 -E 'error:' | sed -E 's/^.*error: //') || true
        fi
        # operand blades from the definition when the report did not run
        if [[ -z $ob ]]; then
            case $p in
                1) ob=$n ;;
                2) ob=$((n * (n - 1) / 2)) ;;
                3) ob=$((1 << (n - 1))) ;;
                4) ob=$((1 << n)) ;;
            esac
        fi
        printf '%ss %sMB %s\n' "$m_wall" "$m_rss" "$m_status" >&2
        printf '%s\t%d\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$kind" "$n" "$ob" $((ob * ob)) "${rb:--}" \
            "${mul:--}" "${add:--}" "$m_wall" "$m_cpu" "$m_rss" "$m_status" "$m_load" "$note" >> "$tsv"
    done
done

# ---- the Markdown fragment -----------------------------------------------------------------
cxx_version=$("$compiler" --version | head -1)
revision=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
[[ -z $(git -C "$root" status --porcelain -- include 2>/dev/null) ]] || revision="$revision + uncommitted changes in include/"
std_flags=$(grep -oE -- '-(O[0-9s]|std=[^ ]+|DNDEBUG)' <<<"$flags" | paste -sd' ')
{
    echo "<!-- written by tools/compile-cost.sh; do not edit by hand -->"
    echo "Machine: \`$cxx_version\`, $(nproc) cores, $(date -u '+%Y-%m-%d %H:%M UTC'); load average at start $load_start,"
    echo "at end $(cut -d' ' -f1-3 /proc/loadavg). Flags of the configured build (\`$build\`): \`$std_flags\`${extra:+, plus \`$extra\`}"
    echo "plus the project's warnings; headers at $revision. One compile at a time, object to /dev/null, $( ((repeat > 1)) && echo "fastest of $repeat" || echo "one run each");"
    echo "*wall* and *cpu* (user + system) in seconds, *peak* the maximum resident set size; *load* the"
    echo "1-minute load average when the compile started, this script's own previous compiles included"
    echo "(about 1 while it runs; on $(nproc) cores, wall well above cpu would mean the compile waited)."
    echo
    echo "| translation unit | file | wall s | cpu s | peak MB | load |"
    echo "| --- | --- | ---: | ---: | ---: | ---: |"
    for row in "${units[@]}"; do
        IFS=$'\t' read -r label file wall cpu rss status l <<<"$row"
        [[ $status == ok ]] || wall="$wall ($status)"
        echo "| $label | \`$file\` | $wall | $cpu | $rss | $l |"
    done
    ((with_heaviest)) || echo "| (c) heaviest | not measured (run with \`--with-heaviest\`) | | | | |"
    echo
    echo "(e) One unit with a tree's RNEA, ABA and CRBA at -O2 (\`bench/compile/tree_dynamics.cpp\`;"
    echo "the arm: \`arm7_dynamics.cpp\`): chains of revolute joints cycling z, y, x and the humanoid of"
    echo "\`bench/chain_trees.hpp\`. Targets (issue 29): the arm ≤ 7 s, the 64-body chain ≤ 20 s, the"
    echo "humanoid ≤ 15 s and ≤ 1.5 GB."
    echo
    echo "| tree | bodies | dofs | wall s | cpu s | peak MB | load |"
    echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    tail -n +2 "$ttsv" | while IFS=$'\t' read -r tree bodies dofs wall cpu rss status l; do
        [[ $status == ok ]] || wall="$wall ($status)"
        echo "| $tree | $bodies | $dofs | $wall | $cpu | $rss | $l |"
    done
    [[ -z $plot ]] || printf '\n![compile seconds against bodies](img/compile_trees.svg)\n'
    echo
    if [[ -n $robots ]]; then
        echo "(f) Real robots as their URDF comes (\`--robots $(basename "$robots")\`: every file converted by"
        echo "\`tools/urdf_to_ctga.py\` with its default options and with \`--floating-base\`), RNEA, ABA and"
        echo "CRBA in one unit at -O2 (\`tree_dynamics.cpp -DCTGA_ROBOT\`). Target (issue 42): ≤ 10 s and ≤ 1 GB."
        echo
        echo "| robot | options | bodies | dofs | wall s | cpu s | peak MB | load |"
        echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"
        tail -n +2 "$rtsv" | while IFS=$'\t' read -r name opt bodies dofs wall cpu rss status l; do
            [[ $status == ok ]] || wall="$wall ($status)"
            echo "| $name | $opt | $bodies | $dofs | $wall | $cpu | $rss | $l |"
        done
        echo
    fi
    echo "One algebra of n generators e1 … en (squares −1, the last 0) and one geometric product of two"
    echo "general operands, evaluated at run time (\`bench/compile/generators.cpp\`, \`-DCTGA_N=n\`)."
    echo "ctga has no global product tables: the blade pairs, signs and the program are computed at"
    echo "compile time for each product's operand types, so each row is the cost of declaring the"
    echo "algebra and compiling that one product. *pairs*: operand blades squared; past"
    echo "\`expr::loop_threshold\` surviving pairs (1,024) the product is looped (blocks of the four low"
    echo "generators through one unrolled kernel, or a loop over bit sets of the surviving pairs) instead"
    echo "of unrolled; *result*: blades of the result type;"
    echo "*cost_of*: multiplications and additions of the generated code (looped: one of each per"
    echo "surviving pair)."
    echo
    echo "| operands | n | operand blades | pairs | result blades | cost_of | wall s | cpu s | peak MB | load |"
    echo "| --- | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: |"
    tail -n +2 "$tsv" | while IFS=$'\t' read -r kind n ob pairs rb mul add wall cpu rss status l note; do
        c="${mul}m ${add}a"
        [[ $mul == - ]] && c=-
        if [[ $status != ok ]]; then wall="$wall (fails)"; fi
        echo "| $kind | $n | $ob | $pairs | $rb | $c | $wall | $cpu | $rss | $l |"
    done
    failed=$(awk -F'\t' 'NR > 1 && $11 != "ok"' "$tsv")
    if [[ -n $failed ]]; then
        echo
        budget=$(grep -oE 'term_budget = [0-9]+' "$root/include/ctga/expr/staging.hpp" | grep -oE '[0-9]+$' || echo '?')
        echo "Limits: the rows marked *fails* do not compile (wall = time to the error). A product node may"
        echo "multiply out at most \`expr::term_budget\` = $budget blade pairs; a product of two multivectors"
        echo "(leaves) cannot stage anything below it, so past the budget it has no valid option and stops:"
        awk -F'\t' 'NR > 1 && $11 != "ok" { printf "- %s, n = %s (%s × %s blades = %s pairs): `%s`\n", $1, $2, $3, $3, $4, $13 }' "$tsv"
    fi
} > "$md"

# ---- the plot ----------------------------------------------------------------------------
if [[ -n $plot ]]; then
    mkdir -p "$(dirname "$plot")"
    if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
        /usr/bin/python3 - "$tsv" "$plot" "$cxx_version" <<'EOF'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
tsv, out, cxx = sys.argv[1:4]
allrows = list(csv.DictReader(open(tsv), delimiter="\t"))
rows = [r for r in allrows if r["status"] == "ok"]
labels = {"vectors": "vector × vector (n blades each)", "bivectors": "bivector × bivector (n(n−1)/2 blades each)",
          "even": "even × even (2^(n−1) blades each)"}
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.4))
for kind, style in (("vectors", "o-"), ("bivectors", "s-"), ("even", "^-")):
    pts = [r for r in rows if r["kind"] == kind]
    if not pts:
        continue
    ns = [int(r["n"]) for r in pts]
    l1, = ax1.plot(ns, [float(r["wall"]) for r in pts], style, label=labels[kind])
    ax2.plot(ns, [float(r["rss"]) for r in pts], style, color=l1.get_color())
    failed = [int(r["n"]) for r in allrows if r["kind"] == kind and r["status"] != "ok"]
    if failed:
        msg = "n ≥ %d: does not compile\n(over the term budget)" % min(failed)
        for ax, key in ((ax1, "wall"), (ax2, "rss")):
            ax.annotate(msg, (ns[-1], float(pts[-1][key])), xytext=(6, -4), textcoords="offset points",
                        fontsize=7, color=l1.get_color(), va="top")
for ax, title in ((ax1, "compile wall time (s)"), (ax2, "peak memory (MB)")):
    ax.set_yscale("log")
    ax.yaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: "%g" % v))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("generators n")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
fig.legend(loc="lower center", ncol=3, fontsize=8, frameon=False)
fig.suptitle("ctga: one algebra and one geometric product per translation unit (" + cxx + ")", fontsize=9)
fig.tight_layout(rect=(0, 0.07, 1, 1))
fig.savefig(out, format="svg")
EOF
    elif command -v gnuplot >/dev/null 2>&1; then
        gnuplot <<EOF
set terminal svg size 1000,400
set output '$plot'
set multiplot layout 1,2
set logscale y
set xlabel 'generators n'
set key top left
set datafile separator tab
ok(s, kind, v) = (strcol(11) eq 'ok' && strcol(1) eq kind) ? v : NaN
set title 'compile wall time (s)'
plot for [k in 'vectors bivectors even'] '$tsv' every ::1 using 2:(ok(0, k, \$8)) with linespoints title k
set title 'peak memory (MB)'
plot for [k in 'vectors bivectors even'] '$tsv' every ::1 using 2:(ok(0, k, \$10)) with linespoints title k
unset multiplot
EOF
    else
        echo "compile-cost: neither /usr/bin/python3 with matplotlib nor gnuplot: no plot" >&2
        plot=
    fi
fi

# the trees' plot: compile seconds against bodies
if [[ -n $plot ]] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    /usr/bin/python3 - "$ttsv" "$(dirname "$plot")/compile_trees.svg" "$cxx_version" <<'EOF'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
tsv, out, cxx = sys.argv[1:4]
rows = [r for r in csv.DictReader(open(tsv), delimiter="\t") if r["status"] == "ok"]
fig, ax = plt.subplots(figsize=(6, 4))
chains = [r for r in rows if r["tree"].startswith("chain")]
ax.plot([int(r["bodies"]) for r in chains], [float(r["wall"]) for r in chains], "o-", label="serial chain")
for r in rows:
    if not r["tree"].startswith("chain"):
        ax.plot([int(r["bodies"])], [float(r["wall"])], "s", label=r["tree"] + " (" + r["dofs"] + " dofs)")
ax.set_xlabel("bodies")
ax.set_ylabel("compile wall time, s (-O2)")
ax.set_ylim(bottom=0)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
ax.set_title("one unit with RNEA + ABA + CRBA (" + cxx + ")", fontsize=9)
fig.tight_layout()
fig.savefig(out, format="svg")
EOF
fi

echo "compile-cost: $md${plot:+, $plot} ($(($(date +%s) - start)) s)" >&2
cat "$md"
