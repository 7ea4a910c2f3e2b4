#!/usr/bin/env bash
# core/'s folders form layers: each includes only itself and the folders before it in
#   integrators model events run analysis
# Prints every include that points up, and fails if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
layers=(integrators model events run analysis)
rank() { local i; for i in "${!layers[@]}"; do [[ ${layers[$i]} == "$1" ]] && echo "$i" && return; done; echo 99; }
bad=0
for file in $(git ls-files 'core/*.h' 'core/*.cpp'); do
  from=$(echo "$file" | cut -d/ -f2)
  for to in $(grep -o '#include "core/[a-z_]*/' "$file" | cut -d/ -f2 | sort -u); do
    if (( $(rank "$to") > $(rank "$from") )); then
      echo "$file includes core/$to/: $from must not depend on $to"
      bad=1
    fi
  done
done
exit $bad
