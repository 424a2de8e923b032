#!/usr/bin/env bash
# The layers of include/ctga point one way: each folder includes only its own headers and those
# of the layers below it.
#
#   support  <  algebra  <  expr  <  operations  <  geometry  <  mechanics  <  collision  <  integrators  <  constraints  <  scenes  <  chains  <  constrained
#
# (core.hpp and ctga.hpp, the umbrella headers, and reference/dense.hpp, which uses only the
# algebra's description, sit outside.) A reader of algebra/ never needs expr/, and so on up.
# Also refused: the core unit (bench/compile/core_only.cpp) reading the derivative headers, and
# a declaration in one layer of a class template that a higher layer defines
# (a forward-declared hook such as `class expression;` in algebra/).
# Usage: check.sh <include/ctga directory>
set -euo pipefail
root=${1:?usage: check.sh include/ctga}
layers=(support algebra expr operations geometry mechanics collision integrators constraints scenes chains constrained)
status=0

rank() {
    local i
    for i in "${!layers[@]}"; do [[ ${layers[$i]} == "$1" ]] && { echo "$i"; return; }; done
    echo -1
}

for ((i = 0; i < ${#layers[@]}; i++)); do
    layer=${layers[$i]}
    [[ -d "$root/$layer" ]] || { echo "layering: missing folder $layer/"; status=1; continue; }
    while IFS= read -r -d '' header; do
        while IFS= read -r target; do
            to=${target%%/*}
            r=$(rank "$to")
            if ((r < 0)); then
                echo "layering: ${header#"$root"/} includes ctga/$target, outside the layers"
                status=1
            elif ((r > i)); then
                echo "layering: ${header#"$root"/} ($layer) includes ctga/$target ($to, a higher layer)"
                status=1
            fi
        done < <(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]ctga/\([^">]*\)[">].*|\1|p' "$header")
    done < <(find "$root/$layer" -name '*.hpp' -print0)
done

# forward-declared hooks: a class template declared without a body in a lower layer
for ((i = 0; i < ${#layers[@]} - 1; i++)); do
    layer=${layers[$i]}
    while IFS= read -r -d '' header; do
        for name in $(grep -hoE '^(template <[^>]*>[[:space:]]*)?(class|struct) [a-z_0-9]+;' "$header" | sed -E 's/.*(class|struct) ([a-z_0-9]+);/\2/'); do
            for ((j = i + 1; j < ${#layers[@]}; j++)); do
                if grep -qE "^(class|struct) $name\b" -r "$root/${layers[$j]}"; then
                    echo "layering: ${header#"$root"/} declares $name, which ${layers[$j]}/ defines (a hook across layers)"
                    status=1
                fi
            done
        done
    done < <(find "$root/$layer" -name '*.hpp' -print0)
done

# The core unit (bench/compile/core_only.cpp: the algebra and the engine, one motor product) does
# not parse the derivative rules nor the Jacobian machinery: evaluating an expression never
# needs them (they are included by operations/jacobian.hpp only).
core_unit="$root/../../bench/compile/core_only.cpp"
derivative_headers=(expr/derivative.hpp expr/differentiate.hpp expr/shared_units.hpp operations/jacobian.hpp)
if [[ -f "$core_unit" ]]; then
    declare -A seen=()
    queue=()
    while IFS= read -r target; do queue+=("$target"); done < <(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]ctga/\([^">]*\)[">].*|\1|p' "$core_unit")
    while ((${#queue[@]})); do
        h=${queue[0]}
        queue=("${queue[@]:1}")
        [[ -n "${seen[$h]:-}" ]] && continue
        seen[$h]=1
        [[ -f "$root/$h" ]] || continue
        while IFS= read -r target; do queue+=("$target"); done < <(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]ctga/\([^">]*\)[">].*|\1|p' "$root/$h")
    done
    for h in "${derivative_headers[@]}"; do
        if [[ -n "${seen[$h]:-}" ]]; then
            echo "layering: the core unit bench/compile/core_only.cpp includes ctga/$h (derivatives belong to operations/jacobian.hpp only)"
            status=1
        fi
    done
    ((status == 0)) && echo "layering: the core unit reads ${#seen[@]} headers, none of the derivative headers"
else
    echo "layering: $core_unit not found"
    status=1
fi

# the same check, on a line: ctga's own headers count as checked
count=$(find "$root" -name '*.hpp' | wc -l)
if ((status == 0)); then echo "layering: $count headers, every include points down"; fi
exit $status
