#!/usr/bin/env bash
# The main job: install, build, and simulate the paper scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec ./build/vibro simulate --preset paper "$@"
