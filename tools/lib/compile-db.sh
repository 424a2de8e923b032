# Shared by tools/compile-stats.sh and tools/compile-cost.sh (source it, do not run it):
# reading a CMake compile_commands.json and timing one compile under /usr/bin/time -v.
#
#   compile_db_read DB [REGEX]   fills the arrays cdb_dirs, cdb_cmds, cdb_files with the entries
#                                whose "file" matches REGEX (all when empty)
#   compile_db_to_devnull CMD    CMD with its object going to /dev/null and the dependency-file
#                                flags dropped, so that a build tree is left untouched
#   time_compile DIR CMD         runs CMD in DIR under /usr/bin/time -v, output discarded; sets
#                                time_wall (seconds), time_cpu (user + system seconds),
#                                time_rss (peak resident set, MB) and time_status (ok or FAIL)

json_unescape() { # the subset CMake writes: \\ and \"
    local s=$1
    s=${s//\\\\/$'\x01'}
    s=${s//\\\"/\"}
    s=${s//$'\x01'/\\}
    printf '%s' "$s"
}

compile_db_read() {
    local db=$1 filter=${2:-} line key val dir="" cmd=""
    cdb_dirs=() cdb_cmds=() cdb_files=()
    # CMake writes one "key": "value" pair per line, "file" after "command".
    local re='^[[:space:]]*"(directory|command|file)":[[:space:]]*"(.*)",?[[:space:]]*$'
    while IFS= read -r line; do
        [[ $line =~ $re ]] || continue
        key=${BASH_REMATCH[1]}
        val=$(json_unescape "${BASH_REMATCH[2]}")
        case $key in
            directory) dir=$val ;;
            command) cmd=$val ;;
            file)
                if [[ -z "$filter" || $val =~ $filter ]]; then
                    cdb_dirs+=("$dir") cdb_cmds+=("$cmd") cdb_files+=("$val")
                fi ;;
        esac
    done < "$db"
}

compile_db_to_devnull() {
    sed -E -e 's/ -o [^ ]+/ -o \/dev\/null/' \
           -e 's/ -M(D|MD)( |$)/ /g' -e 's/ -M(T|F|Q) [^ ]+//g' <<<"$1"
}

time_compile() {
    local dir=$1 cmd=$2 out
    out=$(mktemp)
    time_status=ok
    /usr/bin/time -v -o "$out" bash -c 'cd "$1" && eval "$2"' _ "$dir" "$cmd" \
        >/dev/null 2>&1 || time_status=FAIL
    time_wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {
                    n = split($2, t, ":"); s = 0
                    for (k = 1; k <= n; ++k) s = s * 60 + t[k]
                    printf "%.2f", s }' "$out")
    time_cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { printf "%.2f", s }' "$out")
    time_rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$out")
    rm -f "$out"
}
