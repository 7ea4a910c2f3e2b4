#!/usr/bin/env bash
# Runs the whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/asan-build.sh, into build-asan/ or $VIBRO_ASAN_DIR), leak checking on.
# Usage: scripts/sanitize.sh   (after scripts/setup.sh --test; CI runs scripts/test.sh first)
# Any sanitizer report ends its test with an error (-fno-sanitize-recover), so ctest fails.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${VIBRO_ASAN_DIR:-build-asan}"
bash scripts/asan-build.sh "$dir"

export ASAN_OPTIONS="detect_leaks=1"
# Mesa's OSMesa/llvmpipe driver (3-D panels) keeps allocations for the life of the process;
# only those are suppressed (tests/lsan.supp), every other leak fails its test.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The differential property tests check a quarter of their scenes here (all of them in the
# normal suite): the same code paths, at twenty times the cost per scene under the sanitizers.
export VIBRO_DIFF_FRACTION=0.25
# Left out: the headless-browser test drives Chromium and node, not our instrumented code; the
# front door's (nginx before replicas, 85 s of attacks and soak) and the MPI test (Open MPI's own
# code, leak checks off) would mostly time other programs. The sweep code they drive is in
# core_test and io_test, which run here. Both run in the normal suite. So does doc_commands,
# which runs every command the docs show end to end (work-precision, sweeps, orbits): over
# ten minutes at the sanitizers' cost, for code the unit tests here already reach; and
# sweep_memory, which measures a streamed sweep's peak memory (the sanitizers' shadow memory is
# no measure of it, and its runs exceed ten minutes at their cost).
# Only the summary is printed, or on failure everything but the passing tests' lines.
log="$dir/ctest.log"
status=0
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)" -LE 'browser|deploy|mpi' -E '^(doc_commands|sweep_memory)$' > "$log" 2>&1 || status=$?
if ((status)); then
  grep -v -E "^ +Start |Passed +[0-9.]+ sec" "$log" | tail -300
  echo "sanitize: FAILED (the whole log: $log)"
  exit "$status"
fi
grep -E "tests passed|Total Test time" "$log"
