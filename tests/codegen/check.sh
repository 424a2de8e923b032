#!/usr/bin/env bash
# Instruction counts of ctga's kernels against the hand-written ones, from the object file:
#   check.sh OBJECT        (fails when a ctga kernel needs more than 1.5× the instructions, or
#                          an algorithm object more than its overload set)
# A kernel's count includes every function it calls in the object (recursively): where the
# compiler declines to inline part of an expression, that code still counts; the padding between
# functions (nop) does not.
set -euo pipefail
obj=$1
listing=$(objdump -dr --no-show-raw-insn "$obj")
body() {  # the disassembly of function $1
    awk -v f="<$1>:" '$2 == f {on = 1; next} on && /^$/ {exit} on' <<<"$listing"
}
count() {  # instructions of function $1 and of the functions it calls
    local seen=" $1 " todo=("$1") n=0 f callee
    while ((${#todo[@]})); do
        f=${todo[0]}
        todo=("${todo[@]:1}")
        n=$((n + $(body "$f" | grep -E '^ +[0-9a-f]+:' | grep -cvE ':\s+nop')))
        for callee in $(body "$f" | awk '/R_X86_64_(PLT32|PC32)/ {sub(/-0x[0-9a-f]+$/, "", $3); print $3}'); do
            if [[ $seen != *" $callee "* ]] && grep -q "<$callee>:" <<<"$listing"; then
                seen+="$callee "
                todo+=("$callee")
            fi
        done
    done
    echo "$n"
}
status=0
for k in momentum bracket; do
    c=$(count "ctga_$k")
    h=$(count "hand_$k")
    ratio=$(awk -v c="$c" -v h="$h" 'BEGIN {printf "%.2f", c / h}')
    verdict=ok
    awk -v c="$c" -v h="$h" 'BEGIN {exit !(h > 0 && c > 0 && c <= 1.5 * h)}' || { verdict=FAIL; status=1; }
    echo "$k: ctga $c instructions, hand-written $h, ratio $ratio: $verdict"
done
# an algorithm object and its overload set: the same code
for k in rnea; do
    c=$(count "object_$k")
    o=$(count "overloads_$k")
    verdict=ok
    ((c > 0 && c == o)) || { verdict=FAIL; status=1; }
    echo "$k: through its algorithm object $c instructions, through its overload set $o: $verdict"
done
exit $status
