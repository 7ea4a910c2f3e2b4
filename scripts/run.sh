#!/usr/bin/env bash
# The main job: install, build, and serve the web page and the API on http://127.0.0.1:8080/
# with the paper scene ready. Extra arguments go to `vibro serve` (e.g. --port 9000).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec ./build/vibro serve "$@"
