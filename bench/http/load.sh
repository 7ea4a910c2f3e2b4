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

# The server's CPU time so far (user + system), in clock ticks.
server_ticks() { awk '{print $14 + $15}' "/proc/$server/stat"; }

run() {  # name, then wrk's own arguments
  local name="$1"
  shift
  local line before after requests
  sleep 2  # let the previous run's queued jobs drain
  before="$(server_ticks)"
  line="$(wrk -t2 -c"$connections" -d"${duration}s" --latency "$@" | grep '^RESULT')"
  after="$(server_ticks)"
  requests="$(sed -n 's/.*requests=\([0-9]*\).*/\1/p' <<< "$line")"
  # CPU per request in the server: its CPU time over the run (wrk runs beside it) / requests.
  echo "$name ${line#RESULT } server_cpu_ms_per_request=$(awk -v t=$((after - before)) \
    -v n="$requests" -v hz="$(getconf CLK_TCK)" 'BEGIN { printf "%.2f", 1000 * t / hz / n }')"
}

echo "vibro serve on $base: $(nproc) cores, $connections connections, ${duration} s per run"
run cached_render_png -s bench/http/cached.lua "$base/api/render?preset=paper&format=png"
SCENE="$work/scene.json" PATH_AND_QUERY="/api/render?format=png" \
  run uncached_render_png -s bench/http/uncached.lua "$base"
SCENE="$work/scene.json" PATH_AND_QUERY="/api/simulate" \
  run uncached_simulate -s bench/http/uncached.lua "$base"
