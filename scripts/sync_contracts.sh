#!/usr/bin/env bash
# Copies the project's contracts (API.md, MODEL.md, kept beside the repository in ../shared/)
# into docs/contracts/, so that links to them work in any clone. ctest `contracts` fails while
# the copies differ from ../shared/ (and is skipped where ../shared/ is not there).
# Usage: scripts/sync_contracts.sh [--check]
set -euo pipefail
cd "$(dirname "$0")/.."
shared="${VIBRO_SHARED:-../shared}"
if [[ ! -f "$shared/API.md" ]]; then
  echo "contracts: $shared/API.md not found: nothing to compare"
  exit 77
fi
status=0
for f in API.md MODEL.md; do
  if [[ "${1:-}" == --check ]]; then
    cmp -s "$shared/$f" "docs/contracts/$f" || { echo "contracts: docs/contracts/$f differs from $shared/$f (run scripts/sync_contracts.sh)"; status=1; }
  else
    cp "$shared/$f" "docs/contracts/$f"
  fi
done
((status == 0)) && echo "contracts: docs/contracts/ matches $shared/"
exit "$status"
