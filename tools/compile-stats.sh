#!/usr/bin/env bash
# Compile-time cost per translation unit: re-runs every compile command of
# $BUILD_DIR/compile_commands.json (default build/) under /usr/bin/time -v, the
# object going to /dev/null, one at a time, and prints a table sorted by wall time.
#
#   bash tools/compile-stats.sh            all translation units
#   bash tools/compile-stats.sh 'tests/'   only files whose path matches the regex
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

json_unescape() { # the subset CMake writes: \\ and \"
    local s=$1
    s=${s//\\\\/$'\x01'}
    s=${s//\\\"/\"}
    s=${s//$'\x01'/\\}
    printf '%s' "$s"
}

# CMake writes one "key": "value" pair per line, "file" after "command".
dirs=() cmds=() files=()
dir="" cmd=""
re='^[[:space:]]*"(directory|command|file)":[[:space:]]*"(.*)",?[[:space:]]*$'
while IFS= read -r line; do
    [[ $line =~ $re ]] || continue
    key=${BASH_REMATCH[1]}
    val=$(json_unescape "${BASH_REMATCH[2]}")
    case $key in
        directory) dir=$val ;;
        command) cmd=$val ;;
        file)
            if [[ -z "$filter" || $val =~ $filter ]]; then
                dirs+=("$dir") cmds+=("$cmd") files+=("$val")
            fi ;;
    esac
done < "$db"

n=${#files[@]}
(( n > 0 )) || { echo "compile-stats: no translation unit matches '${filter}'" >&2; exit 1; }

tmp=$(mktemp)
trap 'rm -f "$tmp" "$tmp.rows"' EXIT
: > "$tmp.rows"
for ((i = 0; i < n; ++i)); do
    f=${files[i]}
    rel=${f#"$root"/}
    printf '[%d/%d] %s\n' $((i + 1)) "$n" "$rel" >&2
    # object to /dev/null; drop dependency-file flags so the build tree is untouched
    c=$(sed -E -e 's/ -o [^ ]+/ -o \/dev\/null/' \
               -e 's/ -M(D|MD)( |$)/ /g' -e 's/ -M(T|F|Q) [^ ]+//g' <<<"${cmds[i]}")
    status=ok
    /usr/bin/time -v -o "$tmp" bash -c 'cd "$1" && eval "$2"' _ "${dirs[i]}" "$c" \
        >/dev/null 2>&1 || status=FAIL
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {
               n = split($2, t, ":"); s = 0
               for (k = 1; k <= n; ++k) s = s * 60 + t[k]
               printf "%.2f", s }' "$tmp")
    rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$tmp")
    printf '%s\t%s\t%s\t%s\n' "$wall" "$rss" "$status" "$rel" >> "$tmp.rows"
done

printf '%8s %8s %6s  %s\n' "wall s" "RSS MB" status file
sort -t $'\t' -k1,1gr "$tmp.rows" | while IFS=$'\t' read -r wall rss status rel; do
    printf '%8s %8s %6s  %s\n' "$wall" "$rss" "$status" "$rel"
done
