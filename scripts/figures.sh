#!/usr/bin/env bash
# Regenerates the figures in docs/images/ from the presets (run after scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/images
vibro=${VIBRO:-./build/vibro}
$vibro render --preset paper -o docs/images/paper.png > /dev/null
$vibro render --preset paper-fig1 -o docs/images/paper-fig1.png > /dev/null
$vibro render --preset paper-fig5 -o docs/images/paper-fig5.svg > /dev/null
$vibro render --preset paper-fig6 -o docs/images/paper-fig6.png > /dev/null
echo '{"plots":[{"kind":"cylinder","pellet":0}],"width":900,"height":700}' > /tmp/vibro_cyl_patch.json
$vibro preset paper | python3 -c '
import json,sys; s=json.load(sys.stdin); s.update(json.load(open("/tmp/vibro_cyl_patch.json"))); print(json.dumps(s))' \
  | $vibro render - -o docs/images/paper-cylinder.png > /dev/null
# The paper scene for print (README, "Figures for print"): a journal's single column (85 mm: the
# portrait of pellet 1 over phi(t)) and double column (170 mm: all three panels), tick labels of
# 8 pt, as PDF and as 300 dpi PNG.
print_size() {  # NAME PLOTS-JSON FIGURE-JSON
  $vibro preset paper | python3 -c '
import json,sys; s=json.load(sys.stdin); plots=json.loads(sys.argv[1])
s["plots"]=[s["plots"][i] for i in plots]; s["figure"]=json.loads(sys.argv[2]); print(json.dumps(s))' \
    "$2" "$3" > /tmp/vibro_print_scene.json
  $vibro render /tmp/vibro_print_scene.json -o "docs/images/$1.png" -o "docs/images/$1.pdf" > /dev/null
}
print_size paper-85mm '[0, 2]' '{"width_mm": 85, "height_mm": 120, "font_pt": 8, "dpi": 300}'
print_size paper-170mm '[0, 1, 2]' '{"width_mm": 170, "height_mm": 130, "font_pt": 8, "dpi": 300}'
$vibro orbit --preset impact-oscillator -o docs/images/orbit-branch-impact-oscillator.png
# A period doubling followed in (Omega, k), over the regime map of the same two (docs/ORBITS.md).
$vibro orbit docs/scenes/impact-oscillator-pd-curve.json -o docs/images/orbit-curves-impact-oscillator.png
$vibro orbit docs/scenes/paper-period6.json -o docs/images/orbit-paper-period6.png
# A branch that crosses a grazing from the non-impacting side (docs/ORBITS.md).
$vibro orbit docs/scenes/stop-grazing-crossing.json -o docs/images/orbit-grazing-crossing.png
# Bifurcation diagrams, regime and impact maps (docs/SWEEPS.md).
$vibro sweep --preset impact-oscillator -o docs/images/bifurcation-impact-oscillator.png
$vibro sweep --preset paper-bifurcation -o docs/images/bifurcation-paper.png
$vibro sweep docs/scenes/impact-oscillator-regimes.json -o docs/images/regime-map-impact-oscillator.png
$vibro sweep docs/scenes/impact-oscillator-impacts.json --plot impact_map \
  -o docs/images/impact-map-impact-oscillator.png
# The largest Lyapunov exponent of the impact oscillator over Ω, and over (Ω, F0) (docs/SWEEPS.md).
$vibro sweep docs/scenes/impact-oscillator-lyapunov.json --plot lyapunov \
  -o docs/images/lyapunov-impact-oscillator.png
$vibro sweep docs/scenes/impact-oscillator-lyapunov-map.json --plot lyapunov_map \
  -o docs/images/lyapunov-map-impact-oscillator.png
# The basins of the impact oscillator's two coexisting period-1 motions (docs/SWEEPS.md).
$vibro sweep docs/scenes/impact-oscillator-basins.json -o docs/images/basins-impact-oscillator.png
# docs/PYTHON.md's figures: its Python blocks run in order in docs/images (the module of build/).
PYTHONPATH="$PWD/build/python" MPLBACKEND=Agg /usr/bin/python3 python/tests/doc_snippets.py docs/PYTHON.md \
  docs/images > /dev/null
echo "figures: docs/images/ regenerated"

# The web page with the paper scene, from a real server, in headless Chromium.
if command -v chromium > /dev/null; then
  port=18765
  $vibro serve --port $port --quiet > /dev/null 2>&1 &
  server=$!
  trap 'kill $server 2> /dev/null' EXIT
  for _ in $(seq 50); do curl -sf "http://127.0.0.1:$port/api/health" > /dev/null && break; sleep 0.1; done
  profile=$(mktemp -d)
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$profile" --hide-scrollbars \
    --window-size=1280,800 --virtual-time-budget=8000 \
    --screenshot="$PWD/docs/images/web-paper.png" "http://127.0.0.1:$port/#preset=paper" 2> /dev/null
  rm -rf "$profile"
  echo "figures: docs/images/web-paper.png"
fi
