#!/usr/bin/env bash
# The tree in the house format (.clang-format): lists every C++ file that differs and fails.
# Fix with: git ls-files '*.h' '*.cpp' '*.c' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format > /dev/null || { echo "check_format: clang-format is not installed"; exit 77; }
git ls-files '*.h' '*.cpp' '*.c' | xargs clang-format --dry-run -Werror
