#!/usr/bin/env bash
# Runs browser_test.mjs, first installing its one npm package (playwright-core, no browser
# download) from the committed lock file if node_modules is missing. Exit 77 means skipped.
# Usage: VIBRO=build/vibro WEB=web tests/browser/run.sh
set -euo pipefail
cd "$(dirname "$0")"

for tool in node npm; do
  if ! command -v "$tool" > /dev/null; then
    echo "browser: skipped ($tool not found; apt-get install nodejs npm chromium)"
    exit 77
  fi
done
if [[ ! -d node_modules/playwright-core ]]; then
  # PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD: the test uses Debian's Chromium, never a downloaded one.
  if ! PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error; then
    echo "browser: skipped (npm ci could not install playwright-core; is the npm registry reachable?)"
    exit 77
  fi
fi
exec node browser_test.mjs "$@"
