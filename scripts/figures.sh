#!/usr/bin/env bash
# Regenerates the figures in docs/images/ from the presets (run after scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/images
vibro=${VIBRO:-./build/vibro}
$vibro render --preset paper -o docs/images/paper.png > /dev/null
$vibro render --preset paper-fig5 -o docs/images/paper-fig5.svg > /dev/null
$vibro render --preset paper-fig6 -o docs/images/paper-fig6.png > /dev/null
echo '{"plots":[{"kind":"cylinder","pellet":0}],"width":900,"height":700}' > /tmp/vibro_cyl_patch.json
$vibro preset paper | python3 -c '
import json,sys; s=json.load(sys.stdin); s.update(json.load(open("/tmp/vibro_cyl_patch.json"))); print(json.dumps(s))' \
  | $vibro render - -o docs/images/paper-cylinder.png > /dev/null
echo "figures: docs/images/ regenerated"
