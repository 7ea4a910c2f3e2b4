#!/usr/bin/env bash
# Two `vibro` binaries' instruction counts (callgrind: the same on a loaded machine as on an idle
# one) for every preset and method, the run's own instructions alone: `vibro simulate` of the
# whole run minus the same command with --t-end 0.001 (start-up, reading, writing), without the
# trust check. Prints a line per preset and method and the ratio CUR / BASE; for a change that
# must not slow the engine, where timings on a shared machine vary by more than what is measured.
# Usage: bash bench/instructions_ab.sh BASE_VIBRO CUR_VIBRO [RTOL] [PRESET...]
set -euo pipefail
base="$1" cur="$2" rtol="${3:-1e-9}"
shift $(($# < 3 ? $# : 3))
presets=("$@")
((${#presets[@]})) || mapfile -t presets < <("$cur" presets |
  python3 -c "import json, sys; print('\n'.join(p['name'] for p in json.load(sys.stdin)))")
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# The instructions `vibro simulate ARGS...` executes.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$@" -o "$out/run.json" > /dev/null 2>&1
  callgrind_annotate "$out/cg" 2> /dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}

printf "%-24s %-7s %14s %14s %7s\n" preset method base cur ratio
for p in "${presets[@]}"; do
  for m in auto dopri5 dop853 radau5; do
    args=(simulate --preset "$p" --method "$m" --rtol "$rtol" --atol "$(python3 -c "print($rtol/100)")" --no-check)
    b=$(($(instructions "$base" "${args[@]}") - $(instructions "$base" "${args[@]}" --t-end 0.001)))
    c=$(($(instructions "$cur" "${args[@]}") - $(instructions "$cur" "${args[@]}" --t-end 0.001)))
    printf "%-24s %-7s %14d %14d %7.4f\n" "$p" "$m" "$b" "$c" "$(python3 -c "print($c / $b)")"
  done
done
