#!/usr/bin/env bash
# Builds the libFuzzer target scene_fuzz (clang, ASan + UBSan; in build-asan/ or $VIBRO_ASAN_DIR)
# and runs it for SECONDS (default 60) on a copy of the seed corpus tests/fuzz/corpus, with the
# scene dictionary. Usage: scripts/fuzz.sh [SECONDS]   (after scripts/setup.sh --test).
# A crash, leak, timeout or broken invariant stops the run, keeps the input as crash-* (or
# leak-*, timeout-*, oom-*) in the build directory and fails the script.
#   scripts/fuzz.sh render [SECONDS]   runs the render fuzzer (tests/fuzz/render_fuzz.cpp) in
# the same build for SECONDS (default 600); VIBRO_RENDER_FUZZ_SEED picks other scenes. A failing
# scene is kept as render_fuzz-failure-*.json in the build directory, a crash's as
# render_fuzz-current.json.
set -euo pipefail
cd "$(dirname "$0")/.."

# The targets live in the sanitizer build (scripts/asan-build.sh): CI compiles vibro once for all.
dir="${VIBRO_ASAN_DIR:-build-asan}"
export ASAN_OPTIONS="detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"  # see sanitize.sh
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

if [[ "${1:-}" == render ]]; then
  seconds="${2:-600}"
  bash scripts/asan-build.sh "$dir" render_fuzz
  echo "fuzz: rendering scenes for ${seconds} s (log: $dir/render_fuzz.log)"
  status=0
  "$dir/tests/fuzz/render_fuzz" --seconds "$seconds" --out "$dir" > "$dir/render_fuzz.log" 2>&1 ||
    status=$?
  tail -30 "$dir/render_fuzz.log"
  exit "$status"
fi

seconds="${1:-60}"
bash scripts/asan-build.sh "$dir" scene_fuzz

# Inputs the fuzzer finds go into a scratch copy: the committed seeds stay small and reviewed.
corpus="$dir/corpus"
rm -rf "$corpus"
cp -r tests/fuzz/corpus "$corpus"
log="$dir/fuzz.log"
echo "fuzz: running for ${seconds} s on $(ls "$corpus" | wc -l) seeds (log: $log)"
status=0
"$dir/tests/fuzz/scene_fuzz" -max_total_time="$seconds" -max_len=4096 -timeout=5 -rss_limit_mb=2048 \
  -dict=tests/fuzz/scene.dict -artifact_prefix="$dir/" -print_final_stats=1 "$corpus" > "$log" 2>&1 ||
  status=$?
# libFuzzer's closing figures: the DONE line (executions, coverage as cov: edges and
# ft: features, corpus size), then runs, speed and memory, each once.
grep -E "^#[0-9]+[[:space:]]+DONE" "$log" || true
grep -E "^Done [0-9]+ runs|average_exec_per_sec|peak_rss_mb" "$log" | awk '!seen[$0]++' || true
if ((status)); then
  grep -E -A40 "ERROR: |invariant violated|==[0-9]+==" "$log" | head -60
  echo "fuzz: FAILED (status $status); the input is in $dir (crash-*, leak-*, timeout-*, oom-*)"
  exit "$status"
fi
echo "fuzz: passed, no crash in ${seconds} s; corpus grew to $(ls "$corpus" | wc -l) inputs"
