#!/usr/bin/env bash
# Installs, builds and runs the whole test suite (GoogleTest through ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --test
ctest --test-dir build --output-on-failure -j"$(nproc)"
