#!/usr/bin/env bash
# What vibro.simulate adds to the engine's run, counted rather than timed (times on a shared
# machine are noise; counts are the same on every run): instructions (callgrind) and heap
# allocations (memcheck, with PYTHONMALLOC=malloc so that Python's objects count too) of
# `python/bench/overhead.py BUILD --calls N PRESET` (N calls of vibro.simulate, each reading the
# events, summary, stats and warnings) against `python_engine_call PRESET N` (the same run called
# from C++), each per call as the difference of 30 and 10 calls, so that start-up cancels.
# Usage: python/bench/overhead_counts.sh [BUILD_DIR] [PRESET]   (default build, paper)
# Needs valgrind and the build's python_engine_call (-DVIBRO_BUILD_BENCH=ON). Takes minutes.
set -euo pipefail
build=$(realpath "${1:-build}")
preset=${2:-paper}
here=$(dirname "$(realpath "$0")")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export PYTHONHASHSEED=0  # the same dicts' layout in every run
python=(/usr/bin/python3 "$here/overhead.py" "$build" --calls)
engine=("$build/python/python_engine_call" "$preset")

# The instructions, or heap allocations, of the command after the first argument.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$out/cg" "${@:2}" >/dev/null 2>"$out/log"
  grep -o 'Collected : [0-9]*' "$out/log" | grep -o '[0-9]*$'
}
allocations() {
  PYTHONMALLOC=malloc valgrind --tool=memcheck --leak-check=no "${@:2}" >/dev/null 2>"$out/log"
  grep -o 'total heap usage: [0-9,]* allocs' "$out/log" | grep -o '[0-9,]* allocs' | tr -d ', allocs'
}
for what in instructions allocations; do
  py10=$($what x "${python[@]}" 10 "$preset")
  py30=$($what x "${python[@]}" 30 "$preset")
  c10=$($what x "${engine[@]}" 10)
  c30=$($what x "${engine[@]}" 30)
  py=$(((py30 - py10) / 20))
  c=$(((c30 - c10) / 20))
  echo "$what per call of $preset: vibro.simulate $py, the engine from C++ $c," \
    "overhead $((py - c)) ($(awk "BEGIN {printf \"%.1f\", 100 * ($py - $c) / $c}") %)"
done
