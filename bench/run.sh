#!/usr/bin/env bash
# Installs the benchmark packages, builds the benchmarks (Release) and runs them with
# repetitions, pinned to one core, writing JSON to $BUILD_DIR/results/ and markdown tables
# (medians, ratios) to stdout.
# Usage: bash bench/run.sh   (BUILD_DIR defaults to build-bench; REPETITIONS to 5)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build-bench}"
reps="${REPETITIONS:-5}"
core="${BENCH_CORE:-1}"

bash scripts/install_packages.sh bench libbenchmark-dev libboost-dev libsundials-dev \
  python3-matplotlib

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DVIBRO_BUILD_BENCH=ON -DVIBRO_BUILD_TESTS=OFF \
  > "$build.log" 2>&1 || { cat "$build.log"; exit 1; }
cmake --build "$build" -j2 --target engine_bench overhead_bench work_precision_bench \
  event_peer_bench trust_bench method_bench png_bench >> "$build.log" 2>&1 || { tail -50 "$build.log"; exit 1; }

mkdir -p "$build/results"
# One core, as the targets are stated; llvmpipe (3-D panel) then gets that core alone too.
for b in engine_bench overhead_bench work_precision_bench event_peer_bench trust_bench method_bench \
         png_bench; do
  echo "bench: running $b" >&2
  LP_NUM_THREADS=1 taskset -c "$core" "$build/bench/$b" \
    --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_min_time=0.05 \
    --benchmark_out="$build/results/$b.json" --benchmark_out_format=json > /dev/null
done
# The paper figure drawn by matplotlib from vibro's run, on the same core (Debian's Python).
cmake --build "$build" -j2 --target vibro >> "$build.log" 2>&1 || { tail -50 "$build.log"; exit 1; }
taskset -c "$core" /usr/bin/python3 bench/peers/figure_matplotlib.py --vibro "$build/vibro" \
  --out "$build/results/matplotlib.json" > /dev/null
python3 bench/report.py "$build/results"
