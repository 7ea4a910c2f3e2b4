#!/usr/bin/env bash
# `vibro sweep` under mpirun (issue 11), on this machine: 3 ranks oversubscribed and a hostfile
# naming localhost twice give the one-process output byte for byte, with and without
# continuation, with each run's Lyapunov exponent (bits carried between ranks and through the
# checkpoint); a rank that crashes ends the job with a message naming the value it ran, the
# finished chains kept in OUT.partial, which a rerun refuses to overwrite and --resume completes,
# again byte for byte. Usage: mpi_sweep_test.sh path/to/vibro
set -euo pipefail
vibro="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
# CI runs as root, which Open MPI refuses unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Under the sanitizers (scripts/sanitize.sh): Open MPI's components, loaded and unloaded by
# MPI_Init and MPI_Finalize, keep allocations that LeakSanitizer cannot name to suppress; memory
# errors are still caught, and the sweep's own code is leak-checked by core_test and io_test.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpi=(mpirun --oversubscribe --mca btl self,vader)
failures=0
check() {  # check NAME CONDITION...
  local name="$1"
  shift
  if "$@"; then echo "PASS $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}

"$vibro" preset impact-oscillator | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["sweep"].update(count=90, transient=40, record=10, continuation="none", lyapunov=True)
json.dump(s, open("none.json", "w"))
s["sweep"].update(count=24, continuation="both", initial_states=3, seed=7)
json.dump(s, open("both.json", "w"))'

for scene in none both; do
  "$vibro" sweep "$scene.json" -o "$scene.one.csv" --threads 1
  "${mpi[@]}" -np 3 "$vibro" sweep "$scene.json" -o "$scene.mpi.csv" --threads 2
  check "3 ranks give the one-process output ($scene)" cmp -s "$scene.one.csv" "$scene.mpi.csv"
  check "no checkpoint is left ($scene)" test ! -e "$scene.mpi.csv.partial"
done

printf 'localhost\nlocalhost\n' > hosts
"${mpi[@]}" --hostfile hosts -np 2 "$vibro" sweep none.json -o hosts.csv --threads 1
check "a hostfile naming localhost twice" cmp -s none.one.csv hosts.csv

# Rank 1 crashes at its first run (the test hook VIBRO_SWEEP_FAIL_RANK).
status=0
VIBRO_SWEEP_FAIL_RANK=1 "${mpi[@]}" -x VIBRO_SWEEP_FAIL_RANK -np 3 "$vibro" sweep none.json \
  -o failed.csv --threads 2 2> failed.err || status=$?
check "a crashed rank ends the job with a failure ($status)" test "$status" -ne 0
check "the message names the rank and the value" \
  grep -q "rank 1 on .* failed while running model.pellets\[0\].Omega = [0-9]" failed.err
check "no output is written" test ! -e failed.csv
check "the finished chains are kept, flagged as a checkpoint" \
  grep -q "^vibro sweep checkpoint v4" failed.csv.partial
status=0
"$vibro" sweep none.json -o failed.csv 2> again.err || status=$?
check "a rerun does not overwrite the checkpoint" grep -q -- '"field":"-o"' again.err
"${mpi[@]}" -np 3 "$vibro" sweep none.json -o failed.csv --threads 2 --resume
check "--resume completes it to the one-process output" cmp -s none.one.csv failed.csv
check "the checkpoint goes once the output is written" test ! -e failed.csv.partial

# A basin sweep (classify attractor): the same attractor ids under MPI as in one process, and
# after a crash and --resume, in the streamed CSV and in the JSON's table.
"$vibro" preset impact-oscillator | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["model"]["pellets"][0]["Omega"] = 6.8
s["sweep"] = {"parameter": "model.pellets[0].phi0", "from": 0.05, "to": 1.5, "count": 9,
              "parameter2": {"parameter": "model.pellets[0].dphi0", "from": -7, "to": 7, "count": 7},
              "transient": 100, "record": 4, "classify": "attractor"}
json.dump(s, open("basins.json", "w"))'
"$vibro" sweep basins.json -o basins.one.csv --threads 1
"$vibro" sweep basins.json -o basins.one.json --threads 1
"${mpi[@]}" -np 3 "$vibro" sweep basins.json -o basins.mpi.csv --threads 2
"${mpi[@]}" -np 3 "$vibro" sweep basins.json -o basins.mpi.json --threads 2
check "3 ranks give the one-process basins CSV" cmp -s basins.one.csv basins.mpi.csv
same_attractors() {
  python3 -c 'import json, sys; a, b = (json.load(open(f)) for f in sys.argv[1:]);
assert a["attractors"] == b["attractors"] and len(a["attractors"]) >= 2
assert a["points"]["attractor"] == b["points"]["attractor"]' "$1" "$2"
}
check "3 ranks give the one-process attractors" same_attractors basins.one.json basins.mpi.json
status=0
VIBRO_SWEEP_FAIL_RANK=1 "${mpi[@]}" -x VIBRO_SWEEP_FAIL_RANK -np 3 "$vibro" sweep basins.json \
  -o basins.failed.csv --threads 2 2> /dev/null || status=$?
"${mpi[@]}" -np 3 "$vibro" sweep basins.json -o basins.failed.csv --threads 2 --resume
check "--resume gives the one-process basins CSV" cmp -s basins.one.csv basins.failed.csv

echo "$failures failed"
((failures == 0))
