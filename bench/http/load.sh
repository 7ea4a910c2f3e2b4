#!/usr/bin/env bash
# Load figures for `vibro serve` on loopback with wrk (Debian's package), each run bounded in
# time: the cached image of a preset, and uncached simulate+render and simulate-only posts.
# Usage: bench/http/load.sh [seconds per run, default 10]   (env: VIBRO, PORT, CONNECTIONS)
set -euo pipefail
cd "$(dirname "$0")/../.."

duration="${1:-10}"
vibro="${VIBRO:-build/vibro}"
port="${PORT:-18181}"
connections="${CONNECTIONS:-16}"
command -v wrk > /dev/null || { echo "load.sh: needs wrk (apt-get install -y wrk)" >&2; exit 1; }
[[ -x "$vibro" ]] || { echo "load.sh: no $vibro (build first, or set VIBRO)" >&2; exit 1; }

work="$(mktemp -d)"
trap 'kill "$server" 2> /dev/null; wait "$server" 2> /dev/null; rm -rf "$work"' EXIT
source bench/http/serve.sh
start_server

run() {  # name, then wrk's own arguments
  local name="$1"
  shift
  local line
  sleep 2  # let the previous run's queued jobs drain
  line="$(wrk -t2 -c"$connections" -d"${duration}s" --latency "$@" | grep '^RESULT')"
  echo "$name ${line#RESULT }"
}

echo "vibro serve on $base: $(nproc) cores, $connections connections, ${duration} s per run"
run cached_render_png -s bench/http/cached.lua "$base/api/render?preset=paper&format=png"
SCENE="$work/scene.json" PATH_AND_QUERY="/api/render?format=png" \
  run uncached_render_png -s bench/http/uncached.lua "$base"
SCENE="$work/scene.json" PATH_AND_QUERY="/api/simulate" \
  run uncached_simulate -s bench/http/uncached.lua "$base"
