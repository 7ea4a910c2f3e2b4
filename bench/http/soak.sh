#!/usr/bin/env bash
# Soak test of `vibro serve` on loopback: a mixed load (cached and uncached renders, bad
# requests) at 64 connections, after a warm-up, while the server's resident memory is sampled
# every second. Bounded in time. Usage: bench/http/soak.sh [seconds, default 60]
# (env: VIBRO, PORT, CONNECTIONS). Prints the wrk summary and the RSS before and after.
set -euo pipefail
cd "$(dirname "$0")/../.."

duration="${1:-60}"
vibro="${VIBRO:-build/vibro}"
port="${PORT:-18182}"
connections="${CONNECTIONS:-64}"
command -v wrk > /dev/null || { echo "soak.sh: needs wrk (apt-get install -y wrk)" >&2; exit 1; }

work="$(mktemp -d)"
sampler=""
trap 'kill $sampler "$server" 2> /dev/null; wait "$server" 2> /dev/null; rm -rf "$work"' EXIT
source bench/http/serve.sh
start_server --connections "$connections"
export SCENE="$work/scene.json"

rss() { awk '/VmRSS/ {print $2}' "/proc/$server/status"; }
echo "soak: $(nproc) cores, $connections connections, warm-up 10 s, then ${duration} s"
wrk -t2 -c"$connections" -d10s -s bench/http/mixed.lua "$base" > /dev/null
after_warmup=$(rss)
(while kill -0 "$server" 2> /dev/null; do rss >> "$work/rss.log"; sleep 1; done) &
sampler=$!
wrk -t2 -c"$connections" -d"${duration}s" --latency -s bench/http/mixed.lua "$base" | grep '^RESULT'
end_rss=$(rss)
max_rss=$(sort -n "$work/rss.log" | tail -1)
echo "rss_kib after_warmup=$after_warmup end=$end_rss max=$max_rss samples=$(wc -l < "$work/rss.log")"
kill -0 "$server" && echo "server still up: yes"
