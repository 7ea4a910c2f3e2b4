#!/usr/bin/env bash
# Issue 33's speed figures for several builds side by side: the impact-oscillator sweep on one
# thread (sweep_bench), Taylor's sweep at rtol 1e-10 (taylor_bench's TaylorSweep, where the build
# has it) and the paper scene under `auto` and DOP853 at rtol 1e-9 and 1e-12 (method_bench, CPU
# time). Each build in turn, ROUNDS times, pinned to one core, so that a machine whose speed drifts
# slows every side alike; then per figure each build's median and its paired ratios to the last
# build (median and range over the rounds; above 1: the last build is faster).
# Usage: bash bench/taylor_ab.sh ROUNDS BUILD_DIR... (each configured with -DVIBRO_BUILD_BENCH=ON,
#   bench/sweep_bench and bench/method_bench built)
set -euo pipefail
rounds="$1"
shift
core="${BENCH_CORE:-1}"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
for r in $(seq "$rounds"); do
  for dir in "$@"; do
    b="$dir/bench"
    echo "taylor_ab: round $r/$rounds, $dir" >&2
    taskset -c "$core" "$b/sweep_bench" --benchmark_filter='Oscillator/1/' 2>/dev/null |
      sed -n 's/.*runs_per_s=\([0-9.]*\)\(k\?\)\/s.*/\1 \2/p' |
      awk -v r="$r" -v d="$dir" '{print r, d, "sweep_bench_runs_per_s", ($2 == "k" ? $1 * 1000 : $1)}' >>"$out"
    if [[ -x "$b/taylor_bench" ]]; then
      taskset -c "$core" "$b/taylor_bench" --benchmark_filter='TaylorSweep/taylor/rtol:1e-10' \
        2>/dev/null | sed -n 's/.*runs_per_s=\([0-9.]*\)\(k\?\)\/s.*/\1 \2/p' |
        awk -v r="$r" -v d="$dir" '{print r, d, "taylor_sweep_1e-10_runs_per_s", ($2 == "k" ? $1 * 1000 : $1)}' >>"$out"
    fi
    taskset -c "$core" "$b/method_bench" \
      --benchmark_filter='Method/paper/(auto|dop853)/rtol:1e-(09|12)$' --benchmark_min_time=0.5 \
      2>/dev/null | awk -v r="$r" -v d="$dir" '/^Method/ {print r, d, $1 "_cpu_ms", $4}' >>"$out"
  done
done
python3 - "$out" "${@: -1}" <<'EOF'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
last = sys.argv[2]
value = {(r, d, k): float(v) for r, d, k, v in rows}
for key in dict.fromkeys(k for _, _, k, _ in rows):
    print(key)
    faster_is_more = key.endswith("runs_per_s")
    for d in dict.fromkeys(d for _, d, k, _ in rows if k == key):
        mine = {r: v for (r, dd, k), v in value.items() if dd == d and k == key}
        line = f"  {d}: median {statistics.median(mine.values()):.4g}"
        ratios = [(value[(r, last, key)] / v if faster_is_more else v / value[(r, last, key)])
                  for r, v in mine.items() if (r, last, key) in value]
        if d != last and ratios:
            line += (f"; {last} faster by {statistics.median(ratios):.3f}x "
                     f"({min(ratios):.3f}-{max(ratios):.3f})")
        print(line)
EOF
