#!/usr/bin/env bash
# Compile-time cost per translation unit: re-runs every compile command of
# $BUILD_DIR/compile_commands.json (default build/) under /usr/bin/time -v, the
# object going to /dev/null, one at a time, and prints a table sorted by wall time.
#
#   bash tools/compile-stats.sh            all translation units
#   bash tools/compile-stats.sh 'tests/'   only files whose path matches the regex
#   EXTRA_CXXFLAGS=-O2 bash tools/compile-stats.sh
#                                          flags appended to every command (after the build's own,
#                                          so -O2 overrides a Release build's -O3)
#   BUDGET='30 1536' ...                   units over 30 s wall or 1536 MB are marked OVER and counted
#
# Needs a configured build tree (bash tools/test.sh, or tools/configure.sh).
# Compile-fail tests show up with status FAIL (expected).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
db=$build/compile_commands.json
filter=${1:-}

[[ -f "$db" ]] || { echo "compile-stats: $db not found; configure first (bash tools/test.sh)" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "compile-stats: /usr/bin/time not found (apt-get install time)" >&2; exit 1; }

# shellcheck source=lib/compile-db.sh
source "$root/tools/lib/compile-db.sh"
compile_db_read "$db" "$filter"
dirs=("${cdb_dirs[@]}") cmds=("${cdb_cmds[@]}") files=("${cdb_files[@]}")

n=${#files[@]}
(( n > 0 )) || { echo "compile-stats: no translation unit matches '${filter}'" >&2; exit 1; }

rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for ((i = 0; i < n; ++i)); do
    f=${files[i]}
    rel=${f#"$root"/}
    printf '[%d/%d] %s\n' $((i + 1)) "$n" "$rel" >&2
    cmd=$(compile_db_to_devnull "${cmds[i]}")
    [[ -z ${EXTRA_CXXFLAGS:-} ]] || cmd=${cmd/" -o /dev/null"/" $EXTRA_CXXFLAGS -o /dev/null"}
    time_compile "${dirs[i]}" "$cmd"
    printf '%s\t%s\t%s\t%s\n' "$time_wall" "$time_rss" "$time_status" "$rel" >> "$rows"
done

read -r budget_s budget_mb <<<"${BUDGET:-30 1536}"
printf '%8s %8s %6s  %s\n' "wall s" "RSS MB" status file
sort -t $'\t' -k1,1gr "$rows" | while IFS=$'\t' read -r wall rss status rel; do
    awk -v w="$wall" -v r="$rss" -v s="$budget_s" -v m="$budget_mb" 'BEGIN { exit !(w > s || r > m) }' && status="$status OVER"
    printf '%8s %8s %6s  %s\n' "$wall" "$rss" "$status" "$rel"
done
over=$(awk -F'\t' -v s="$budget_s" -v m="$budget_mb" '$1 > s || $2 > m' "$rows" | wc -l)
echo "compile-stats: $n units, $over over the budget of $budget_s s / $budget_mb MB${EXTRA_CXXFLAGS:+ (with $EXTRA_CXXFLAGS)}"
