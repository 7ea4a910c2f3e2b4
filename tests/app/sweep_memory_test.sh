#!/usr/bin/env bash
# `vibro sweep -o OUT.csv` writes the points as chains finish: its peak memory does not grow with
# the number of runs. A basin sweep of the impact oscillator over 60 × 60 and 180 × 180 initial
# states (9× the runs, each run short); kept in memory, the larger sweep's points and runs
# (about 1 KB a run) would add some 30 MB. About 1 minute on an idle 2-core machine. Also: the streamed CSV is the one the in-memory
# writer makes (the JSON's columns, checked on the small sweep), and one thread and two give
# the same file.
set -euo pipefail
vibro=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

scene() {  # N [TRANSIENT]: an N × N basin sweep, 20 transient and 4 recorded periods a run
  python3 - "$1" "${2:-20}" > "$dir/basins$1.json" <<'PY'
import json, sys
n, transient = int(sys.argv[1]), int(sys.argv[2])
print(json.dumps({
    "model": {"R": 0.5, "alpha0": 0.0,
              "pellets": [{"m": 0.1, "phi0": 0.1, "dphi0": 0.0, "F0": 0.3, "Omega": 6.8, "psi": 0.0}],
              "limiters": [{"angle": 0.0, "k": 0.8}]},
    "t_end": 1.0, "solver": {"method": "auto", "rtol": 1e-9, "atol": 1e-12},
    "sweep": {"parameter": "model.pellets[0].phi0", "from": 0.05, "to": 1.5, "count": n,
              "parameter2": {"parameter": "model.pellets[0].dphi0", "from": -7.0, "to": 7.0, "count": n},
              "transient": transient, "record": 4, "classify": "attractor"}}))
PY
}

peak_kb() {  # N THREADS: the sweep's maximum resident set, KB
  /usr/bin/time -f '%M' -o "$dir/time$1" "$vibro" sweep "$dir/basins$1.json" -o "$dir/out$1-$2.csv" \
    --threads "$2" > /dev/null
  tail -1 "$dir/time$1"
}

scene 60
scene 180
small=$(peak_kb 60 2)
large=$(peak_kb 180 2)
echo "peak memory: 60 x 60 runs $small KB, 180 x 180 runs $large KB"
if (( large > small + 12000 )); then
  echo "FAIL: the peak memory grew by $((large - small)) KB for 9x the runs" >&2
  exit 1
fi

# The streamed CSV is the in-memory writer's: rows, order and attractor ids (from the JSON), on a
# sweep whose runs settle (100 transient periods: several attractors, ids renumbered).
scene 12 100
peak_kb 12 1 > /dev/null
peak_kb 12 2 > /dev/null
cmp "$dir/out12-1.csv" "$dir/out12-2.csv" || { echo "FAIL: 1 and 2 threads differ" >&2; exit 1; }
"$vibro" sweep "$dir/basins12.json" -o "$dir/out12.json" --threads 2
python3 - "$dir/out12.json" "$dir/out12-2.csv" <<'PY'
import csv, json, sys
j = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
p = j["points"]
assert len(rows) == len(p["phi"]), (len(rows), len(p["phi"]))
for k, row in enumerate(rows):
    assert float(row["model.pellets[0].phi0"]) == p["value"][k], k
    assert float(row["model.pellets[0].dphi0"]) == p["value2"][k], k
    assert float(row["phi"]) == p["phi"][k], k
    assert int(row["attractor"]) == p["attractor"][k], (k, row["attractor"], p["attractor"][k])
assert len(j["attractors"]) >= 2, j["attractors"]
print("streamed CSV matches the JSON:", len(rows), "rows,", len(j["attractors"]), "attractors")
PY
echo "sweep memory: ok"
