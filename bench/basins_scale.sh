#!/usr/bin/env bash
# The million-cell basin map, docs/scenes/million-cell-basins.json (1000 × 1000 initial states of
# the impact oscillator; N × N with N given), written as CSV as its chains finish: wall time, CPU
# time and peak memory (/usr/bin/time -v), with the machine's load before and after
# (docs/SCALE.md).
#   bench/basins_scale.sh [N] [THREADS]     (VIBRO=path/to/vibro, default ./build/vibro)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000}
threads=${2:-2}
vibro=${VIBRO:-./build/vibro}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 - "$n" docs/scenes/million-cell-basins.json > "$dir/scene.json" <<'PY'
import json, sys
n = int(sys.argv[1])
s = json.load(open(sys.argv[2]))
s["sweep"]["count"] = n
s["sweep"]["parameter2"]["count"] = n
print(json.dumps(s))
PY
echo "basins $n x $n ($((n * n)) runs), $threads threads, $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/time -v -o "$dir/time" nice "$vibro" sweep "$dir/scene.json" -o "$dir/basins.csv" --threads "$threads"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
grep -E "Elapsed|User time|System time|Maximum resident" "$dir/time"
awk '/Elapsed/ {print "wall time:", $NF} /Maximum resident/ {printf "peak memory: %.1f MB\n", $NF / 1024}' "$dir/time"
echo "CSV: $(wc -l < "$dir/basins.csv") lines, $(du -h "$dir/basins.csv" | cut -f1)"
python3 - "$dir/basins.csv" <<'PY'
import collections, csv, sys
cells = collections.Counter()
last = None
for row in csv.DictReader(open(sys.argv[1])):
    key = (row["model.pellets[0].phi0"], row["model.pellets[0].dphi0"])
    if key != last:
        cells[int(row["attractor"])] += 1
        last = key
print("cells per attractor:", dict(sorted(cells.items())))
PY
