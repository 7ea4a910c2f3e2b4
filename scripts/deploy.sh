#!/usr/bin/env bash
# The service behind its front door (docs/DEPLOY.md): N `vibro serve` replicas on loopback ports
# PORT+1 … PORT+N and nginx in front on PORT, with deploy/nginx/vibro.conf.in. Runs in the
# foreground; a replica that dies is restarted; Ctrl-C or SIGTERM stops nginx and every replica.
# Installs nginx if missing, and builds vibro if build/vibro is missing.
# Usage: scripts/deploy.sh [--port P] [--replicas N] [--host ADDRESS] [--run DIR] [--vibro PATH]
#                          [-- FLAGS]
#   --host   where nginx listens (default 127.0.0.1; 0.0.0.0 for every interface)
#   --run    the run directory: nginx.conf, logs, pids (default /tmp/vibro-deploy-PORT)
#   --vibro  the vibro program (default build/vibro, built if missing)
#   FLAGS    passed to every `vibro serve` (e.g. -- --threads 2 --max-t-end 100)
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$PWD"

port=8080
replicas=2
host=127.0.0.1
run=""
vibro=""
serve_flags=()
while (($#)); do
  case "$1" in
    --port) port="$2"; shift 2 ;;
    --replicas) replicas="$2"; shift 2 ;;
    --host) host="$2"; shift 2 ;;
    --run) run="$2"; shift 2 ;;
    --vibro) vibro="$2"; shift 2 ;;
    --) shift; serve_flags=("$@"); break ;;
    *) echo "deploy: unknown option $1 (see the usage at the top of $0)" >&2; exit 2 ;;
  esac
done
[[ "$port" =~ ^[0-9]+$ ]] && ((port >= 1 && port + replicas <= 65535)) ||
  { echo "deploy: --port must leave room for the replicas' ports up to 65535" >&2; exit 2; }
[[ "$replicas" =~ ^[0-9]+$ ]] && ((replicas >= 1 && replicas <= 64)) ||
  { echo "deploy: --replicas must be from 1 to 64" >&2; exit 2; }
run="${run:-/tmp/vibro-deploy-$port}"

command -v nginx > /dev/null || [[ -x /usr/sbin/nginx ]] || bash scripts/install_packages.sh deploy nginx
nginx_bin="$(command -v nginx || echo /usr/sbin/nginx)"
if [[ -z "$vibro" ]]; then
  vibro="$repo/build/vibro"
  [[ -x "$vibro" ]] || bash scripts/setup.sh
fi

# The request body limit is the service's: nginx refuses what a replica would.
max_body=65536
for ((i = 0; i < ${#serve_flags[@]}; i++)); do
  [[ "${serve_flags[$i]}" == --max-body ]] && max_body="${serve_flags[$((i + 1))]}"
done

mkdir -p "$run"/tmp/{body,proxy,fastcgi,uwsgi,scgi}
# The page is served from a copy in the run directory: nginx's workers may not be able to read
# the repository (a clone in /root, workers running as nobody).
rm -rf "$run/web"
cp -r "$repo/web" "$run/web"
user_line=""
if [[ $(id -u) -eq 0 ]]; then
  # nginx's workers drop root; they read the page and write their temporary files as nobody.
  user_line="user nobody nogroup;"
  chown -R nobody:nogroup "$run/tmp"
  chmod -R a+rX "$run/web"
  chmod 755 "$run"
fi
servers="" replica_upstreams="" job_routes=""
for ((k = 1; k <= replicas; k++)); do
  servers+="        server 127.0.0.1:$((port + k)) max_fails=3 fail_timeout=2s;"$'\n'
  replica_upstreams+="    upstream replica$k { server 127.0.0.1:$((port + k)); }"$'\n'
  job_routes+="        location ^~ /api/jobs/r$k- { proxy_pass http://replica$k; }"$'\n'
done
conf="$run/nginx.conf"
awk -v run="$run" -v user="$user_line" -v host="$host" -v port="$port" -v web="$run/web" \
    -v body="$max_body" -v count="$replicas" -v servers="$servers" \
    -v replicas="$replica_upstreams" -v routes="$job_routes" '
  { gsub(/@RUN@/, run); gsub(/@USER@/, user); gsub(/@HOST@/, host); gsub(/@PORT@/, port);
    gsub(/@WEB@/, web); gsub(/@MAX_BODY@/, body); gsub(/@REPLICA_COUNT@/, count) }
  /^@SERVERS@$/ { printf "%s", servers; next }
  /^@REPLICAS@$/ { printf "%s", replicas; next }
  /^@JOB_ROUTES@$/ { printf "%s", routes; next }
  { print }' deploy/nginx/vibro.conf.in > "$conf"
"$nginx_bin" -t -q -p "$run" -c "$conf" -e "$run/error.log"

pids=()
nginx_pid=""
start_replica() {  # start_replica K
  "$vibro" serve --host 127.0.0.1 --port $((port + $1)) --replica "$1" --quiet \
    --web "$repo/web" "${serve_flags[@]}" >> "$run/replica$1.log" 2>&1 &
  pids[$1]=$!
  echo "$!" > "$run/replica$1.pid"
}
stop_all() {
  trap - INT TERM EXIT
  [[ -n "$nginx_pid" ]] && kill -TERM "$nginx_pid" 2> /dev/null || true
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2> /dev/null || true; done
  wait 2> /dev/null || true
  rm -f "$run"/replica*.pid
  echo "deploy: stopped nginx and ${replicas} replicas"
}
trap stop_all EXIT
trap 'exit 0' INT TERM

for ((k = 1; k <= replicas; k++)); do start_replica "$k"; done
"$nginx_bin" -p "$run" -c "$conf" -e "$run/error.log" -g "daemon off;" &
nginx_pid=$!
echo "deploy: http://$host:$port/ → nginx → ${replicas} replicas on 127.0.0.1:$((port + 1))…$((port + replicas))"
echo "deploy: config $conf, access log $run/access.log, replicas' logs $run/replica*.log"

while true; do
  sleep 0.5
  if ! kill -0 "$nginx_pid" 2> /dev/null; then
    echo "deploy: nginx stopped (see $run/error.log)" >&2
    exit 1
  fi
  for ((k = 1; k <= replicas; k++)); do
    if ! kill -0 "${pids[$k]}" 2> /dev/null; then
      wait "${pids[$k]}" 2> /dev/null || true
      echo "deploy: replica $k (port $((port + k))) died; restarting it" >&2
      start_replica "$k"
    fi
  done
done
