# Sourced by the load scripts: starts `vibro serve` on loopback and waits for it, then writes
# the paper scene with a T_END_HERE placeholder that the Lua scripts fill per request.
# Needs: vibro, port, work (a scratch folder); sets: server (its pid), base (its URL).
# Extra arguments go to `vibro serve`.
start_server() {
  "$vibro" serve --host 127.0.0.1 --port "$port" --quiet "$@" > "$work/serve.out" 2>&1 &
  server=$!
  for _ in $(seq 50); do
    curl -sf "http://127.0.0.1:$port/api/health" > /dev/null && break
    sleep 0.1
  done
  base="http://127.0.0.1:$port"
  "$vibro" preset paper | sed 's/"t_end": [0-9.]*/"t_end": T_END_HERE/' > "$work/scene.json"
  grep -q T_END_HERE "$work/scene.json"
}
