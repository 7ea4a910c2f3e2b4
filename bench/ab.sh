#!/usr/bin/env bash
# Two builds' benchmarks side by side, for a change that must not slow anything: runs each
# benchmark binary of BASE and of CUR in turn, ROUNDS times (alternating, so that a machine whose
# load drifts slows both alike), pinned to one core, then prints per benchmark the median CPU time
# of each side and their ratio (bench/compare.py; a ratio past 1.05 is flagged).
# Usage: bash bench/ab.sh BASE_BUILD CUR_BUILD [ROUNDS] [BINARY...]
#   BASE_BUILD, CUR_BUILD: build directories configured with -DVIBRO_BUILD_BENCH=ON, the
#   benchmarks built (bench/run.sh's list); ROUNDS defaults to 5.
set -euo pipefail
cd "$(dirname "$0")/.."
base="$1" cur="$2" rounds="${3:-5}"
shift $(($# < 3 ? $# : 3))
binaries=("$@")
((${#binaries[@]})) || binaries=(engine_bench overhead_bench work_precision_bench event_peer_bench
  trust_bench method_bench png_bench)
core="${BENCH_CORE:-1}"
out="$(mktemp -d)"
for r in $(seq "$rounds"); do
  for side in base cur; do
    dir="$base"
    [[ "$side" == cur ]] && dir="$cur"
    mkdir -p "$out/$side/$r"
    for b in "${binaries[@]}"; do
      echo "ab: round $r/$rounds, $side, $b" >&2
      LP_NUM_THREADS=1 taskset -c "$core" "$dir/bench/$b" --benchmark_min_time=0.1 \
        --benchmark_out="$out/$side/$r/$b.json" --benchmark_out_format=json > /dev/null
    done
  done
done
# Every round's runs of a benchmark in one file per binary and side, as compare.py reads them.
python3 - "$out" "${binaries[@]}" <<'PY'
import json, os, sys
out, binaries = sys.argv[1], sys.argv[2:]
for side in ("base", "cur"):
    for b in binaries:
        rounds = sorted(r for r in os.listdir(os.path.join(out, side)) if r.isdigit())
        runs = [x for r in rounds for x in json.load(open(os.path.join(out, side, r, b + ".json")))["benchmarks"]]
        json.dump({"benchmarks": runs}, open(os.path.join(out, side, b + ".json"), "w"))
PY
python3 bench/compare.py --time cpu "$out/base" "$out/cur"
echo "ab: the runs are in $out" >&2
