#!/usr/bin/env bash
# Shows a build's progress while its output goes to a log: reads the output of `cmake --build`
# on stdin, appends it whole to LOG, and prints its percentage on stderr, in place on a terminal
# and a line per tenth otherwise (a CI log). Usage: cmake --build ... 2>&1 |
# scripts/build_progress.sh WHO LOG  (WHO prefixes the lines, as in "setup: building 40%").
set -uo pipefail
who="$1"
log="$2"
last=-10  # none yet: the first percentage shows
while IFS= read -r line; do
  printf '%s\n' "$line" >> "$log"
  [[ $line =~ ^\[\ *([0-9]+)%\] ]] || continue
  pct=$((10#${BASH_REMATCH[1]}))
  if [[ -t 2 ]]; then
    printf '\r%s: building %3d%%' "$who" "$pct" >&2
  elif ((pct / 10 > last / 10)); then
    echo "$who: building $pct%" >&2
  fi
  last=$pct
done
[[ -t 2 ]] && ((last >= 0)) && echo >&2
exit 0
