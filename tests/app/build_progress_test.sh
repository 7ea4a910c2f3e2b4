#!/usr/bin/env bash
# The set-up shows its build's progress (scripts/build_progress.sh): the percentages of the
# build's output on stderr, a line per tenth when stderr is no terminal, and the whole output in
# the log. Usage: build_progress_test.sh path/to/scripts/build_progress.sh
set -uo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf '%s\n' "-- configuring" "[  3%] Building CXX object a.o" "[  7%] Building CXX object b.o" \
  "[ 45%] Linking CXX static library x.a" "warning: something" "[100%] Built target vibro" |
  bash "$1" setup "$work/build.log" 2> "$work/err.txt" > "$work/out.txt"
expected=$'setup: building 3%\nsetup: building 45%\nsetup: building 100%'
if [[ "$(cat "$work/err.txt")" == "$expected" ]] && [[ ! -s "$work/out.txt" ]] &&
  (($(wc -l < "$work/build.log") == 6)); then
  echo "PASS the build's progress shows and the log keeps all"
else
  echo "FAIL the build's progress shows and the log keeps all"
  cat "$work/err.txt"
  exit 1
fi
