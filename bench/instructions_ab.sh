#!/usr/bin/env bash
# Two `vibro` binaries' instruction counts (callgrind: the same on a loaded machine as on an idle
# one) for every preset and method, the run's own instructions alone: those inside
# vibro::simulate(Model, SimOptions) (callgrind --toggle-collect), without the trust check, so
# that start-up, reading and writing, which vary by some thousand instructions between
# invocations, count for nothing (a run of a few steps costs only tens of thousands). Prints a
# line per preset and method and the ratio CUR / BASE; for a change that must not slow the
# engine, where timings on a shared machine vary by more than what is measured.
# Usage: [METHODS="dopri5 dop853"] bash bench/instructions_ab.sh BASE_VIBRO CUR_VIBRO [RTOL] [PRESET...]
set -euo pipefail
base="$1" cur="$2" rtol="${3:-1e-9}"
shift $(($# < 3 ? $# : 3))
presets=("$@")
((${#presets[@]})) || mapfile -t presets < <("$cur" presets |
  python3 -c "import json, sys; print('\n'.join(p['name'] for p in json.load(sys.stdin)))")
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# The instructions `vibro simulate ARGS...` executes inside the engine's entry point.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$out/cg" \
    --toggle-collect='vibro::simulate(vibro::Model const&, vibro::SimOptions const&)' \
    "$@" -o "$out/run.json" > /dev/null 2>&1
  callgrind_annotate "$out/cg" 2> /dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'
}

printf "%-24s %-7s %14s %14s %7s\n" preset method base cur ratio
for p in "${presets[@]}"; do
  for m in ${METHODS:-auto dopri5 dop853 radau5}; do
    args=(simulate --preset "$p" --method "$m" --rtol "$rtol" --atol "$(python3 -c "print($rtol/100)")" --no-check)
    b=$(instructions "$base" "${args[@]}")
    c=$(instructions "$cur" "${args[@]}")
    printf "%-24s %-7s %14d %14d %7.4f\n" "$p" "$m" "$b" "$c" "$(python3 -c "print($c / $b)")"
  done
done
