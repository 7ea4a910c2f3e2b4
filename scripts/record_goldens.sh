#!/usr/bin/env bash
# Records what a behaviour-keeping change of core/ must keep, byte for byte, into DIR:
# every preset's run under every method (JSON, wall-clock fields removed), its sampled
# trajectory (CSV) and its figure (SVG); every corpus scene's run; the docs' sweeps and orbits;
# work-precision's errors and steps;
# and the trust scan's per-run table over the given seeds. Compare two recordings with
# `diff -r BEFORE AFTER`.
#   scripts/record_goldens.sh DIR [VIBRO] [TRUST_SCAN] [SEEDS] [COUNT]
set -euo pipefail
out=${1:?usage: record_goldens.sh DIR [VIBRO] [TRUST_SCAN] [SEEDS] [COUNT]}
vibro=${2:-build/vibro}
scan=${3:-build/tests/differential/trust_scan}
seeds=${4:-"1 2"}
count=${5:-300}
mkdir -p "$out"/{runs,trajectories,figures,corpus,sweeps,orbits,work_precision,trust}

# Wall-clock fields differ run to run; everything else must not.
strip() { python3 -c '
import json, sys
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items()
                if not (k.endswith("wall_ms") or k in ("elapsed_ms", "wall_s", "seconds", "runs_per_second"))}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
print(json.dumps(clean(json.load(sys.stdin)), indent=1, sort_keys=True))'; }

# Work-precision's times are wall clock: every *_ms goes.
strip_ms() { python3 -c '
import json, sys
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items() if not k.endswith("_ms")}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
print(json.dumps(clean(json.load(sys.stdin)), indent=1, sort_keys=True))'; }

presets=$("$vibro" presets | python3 -c 'import json,sys; print(" ".join(p["name"] for p in json.load(sys.stdin)))')
for p in $presets; do
  for m in auto dopri5 dop853 radau5; do
    "$vibro" simulate --preset "$p" --method "$m" | strip > "$out/runs/$p.$m.json"
  done
  "$vibro" simulate --preset "$p" --trajectories --what trajectory -o "$out/trajectories/$p.csv" >/dev/null
  "$vibro" render --preset "$p" -o "$out/figures/$p.svg" >/dev/null
done
for f in tests/reference/corpus/*.json tests/differential/corpus/*.json docs/scenes/*.json; do
  name=$(basename "$(dirname "$f")")-$(basename "$f" .json)
  "$vibro" simulate "$f" 2>&1 | strip > "$out/corpus/$name.json" || echo "refused" > "$out/corpus/$name.json"
done
for p in impact-oscillator paper-bifurcation; do
  "$vibro" sweep --preset "$p" --threads 2 -o "$out/sweeps/$p.csv" >/dev/null
done
for f in docs/scenes/impact-oscillator-*.json; do
  "$vibro" sweep "$f" --threads 2 -o "$out/sweeps/$(basename "$f" .json).csv" >/dev/null
done
"$vibro" orbit --preset impact-oscillator | strip > "$out/orbits/impact-oscillator.json"
for p in paper chatter; do
  "$vibro" work-precision --preset "$p" | strip_ms > "$out/work_precision/$p.json"
done
for s in $seeds; do
  # The check's cost (its last column) is a wall-clock ratio.
  "$scan" --count "$count" --seed "$s" --jobs 2 --out "$out/trust/runs.tmp" | sed 's/|[^|]*|$/|/' > "$out/trust/summary-$s.txt"
  cut -d, -f1-10 "$out/trust/runs.tmp" > "$out/trust/runs-$s.csv" && rm "$out/trust/runs.tmp"
done
echo "recorded into $out"
