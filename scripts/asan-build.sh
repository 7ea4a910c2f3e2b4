#!/usr/bin/env bash
# Builds vibro with clang, AddressSanitizer and UndefinedBehaviorSanitizer, instrumented for
# libFuzzer's coverage too, so that the sanitized test suite (scripts/sanitize.sh) and the fuzz
# target (scripts/fuzz.sh) share one build. Usage: scripts/asan-build.sh DIR [TARGET...]
# Needs the libraries of scripts/setup.sh --test; installs clang and its runtimes if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$1"
shift

# clang-14 and its sanitizer and libFuzzer runtimes (libclang-rt-14-dev) from Debian 12.
bash scripts/install_packages.sh asan-build clang libclang-rt-14-dev ccache

# fuzzer-no-link only adds coverage counters; the ASan runtime answers them in ordinary programs.
# Line tables are all a sanitizer's stack trace needs, and compile faster than full -g.
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
mkdir -p "$dir"
echo "asan-build: building $dir ${*:-(everything)} with clang, ASan + UBSan, -O1"
CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DVIBRO_BUILD_FUZZ=ON \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
  > "$dir/build.log" 2>&1 || { cat "$dir/build.log"; exit 1; }
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" "${targets[@]}" -j"${VIBRO_JOBS:-$(nproc)}" >> "$dir/build.log" 2>&1 ||
  { tail -50 "$dir/build.log"; exit 1; }
