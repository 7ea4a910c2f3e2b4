#!/usr/bin/env bash
# Scaling of `vibro sweep` under mpirun on this machine (docs/SCALE.md): the impact-oscillator
# preset swept over 1,000 values of Omega (50 transient and 20 recorded periods, no
# continuation), in one process on 1 and all threads and under mpirun with 1, 2 and 4 ranks of
# one thread each (oversubscribed past the cores), each checked byte for byte against the first.
# Prints the median wall time of REPEATS runs (default 3) and the speed-up per configuration.
# Usage: bench/mpi_scaling.sh [path/to/vibro] [REPEATS]
set -euo pipefail
vibro="$(realpath "${1:-build/vibro}")"
repeats="${2:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$vibro" preset impact-oscillator | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["sweep"].update(count=1000, transient=50, record=20, continuation="none", initial_states=1)
json.dump(s, open("scene.json", "w"))'

median_of() {  # median_of NAME COMMAND...: runs it $repeats times, prints the median seconds
  local name="$1"
  shift
  local times=()
  for ((k = 0; k < repeats; k++)); do
    rm -f "$name.csv"
    local t0 t1
    t0=$(date +%s.%N)
    "$@" -o "$name.csv" > /dev/null 2>&1
    t1=$(date +%s.%N)
    times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')")
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((repeats + 1) / 2))p"
}

cores=$(nproc)
printf '%-34s %8s %8s %s\n' configuration seconds speed-up output
base=""
row() {  # row LABEL NAME COMMAND...
  local label="$1" name="$2"
  shift 2
  local s
  s=$(median_of "$name" "$@")
  [[ -z "$base" ]] && base="$s"
  local same="identical"
  [[ "$name" == one ]] || cmp -s one.csv "$name.csv" || same="DIFFERS"
  printf '%-34s %8.2f %7.2fx %s\n' "$label" "$s" "$(awk -v a="$base" -v b="$s" 'BEGIN { print a / b }')" "$same"
}
mpi=(mpirun --oversubscribe --mca btl self,vader)
row "1 process, 1 thread" one "$vibro" sweep scene.json --threads 1
row "1 process, $cores threads" threads "$vibro" sweep scene.json --threads "$cores"
row "mpirun -np 1, 1 thread" np1 "${mpi[@]}" -np 1 "$vibro" sweep scene.json --threads 1
row "mpirun -np 2, 1 thread each" np2 "${mpi[@]}" -np 2 "$vibro" sweep scene.json --threads 1
row "mpirun -np 4, 1 thread each" np4 "${mpi[@]}" -np 4 "$vibro" sweep scene.json --threads 1
