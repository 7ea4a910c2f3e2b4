#!/usr/bin/env bash
# The `vibro` command line (app/main.cpp, CLI11): --help on the program and on every subcommand
# names each option; bad usage is {"error", "field"} JSON on stderr naming the option, exit 2;
# the serve flags reach the server's config. Usage: cli_test.sh path/to/vibro
set -uo pipefail
vibro="$1"
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
server=""
disk=""
cleanup() {
  [[ -n "$server" ]] && kill "$server" 2> /dev/null && wait "$server" 2> /dev/null
  [[ -n "$disk" ]] && umount "$disk"
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work" || exit 1

failures=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

# help NAME ARGS... -- OPTION...: `vibro ARGS` exits 0 and its stdout names every OPTION.
help() {
  local name="$1" args=() missing=()
  shift
  while [[ "$1" != "--" ]]; do args+=("$1"); shift; done
  shift
  local out status=0
  out="$("$vibro" "${args[@]}" 2>&1)" || status=$?
  for option in "$@"; do grep -qF -- "$option" <<< "$out" || missing+=("$option"); done
  if ((status == 0 && ${#missing[@]} == 0)); then pass "$name"; else
    fail "$name (exit $status, missing: ${missing[*]})"; echo "$out"; fi
}

# usage NAME FIELD [MESSAGE] -- ARGS...: `vibro ARGS` exits 2 with one line of JSON on stderr
# whose field is FIELD (and whose error is MESSAGE, when given).
usage() {
  local name="$1" field="$2" message="" status=0
  shift 2
  [[ "$1" != "--" ]] && { message="$1"; shift; }
  shift
  "$vibro" "$@" > out.txt 2> err.txt < /dev/null || status=$?
  if ((status == 2)) && python3 - "$field" "$message" << 'PY'; then pass "$name"; else
import json, sys
error = json.loads(open("err.txt").read())
assert set(error) == {"error", "field"}, error
assert error["field"] == sys.argv[1], error
assert not sys.argv[2] or error["error"] == sys.argv[2], error
PY
    fail "$name (exit $status)"; cat err.txt; fi
}

scene=(SCENE --preset --t-end --method --rtol --atol --deadline-ms --no-check --trajectories)
help "vibro --help lists the commands" --help -- simulate render work-precision sweep orbit plot \
  serve presets preset help
help "vibro help lists the commands" help -- simulate render work-precision sweep orbit serve
help "simulate --help" simulate --help -- "${scene[@]}" -o --output --what
help "render --help" render --help -- "${scene[@]}" -o --output
help "work-precision --help" work-precision --help -- "${scene[@]}" -o --output --repeats
help "sweep --help" sweep --help -- "${scene[@]}" -o --output --threads --plot --pellet \
  --coordinate --resume
help "vibro help sweep" help sweep -- "${scene[@]}" --threads --resume
help "orbit --help" orbit --help -- "${scene[@]}" -o --output
help "plot --help" plot --help -- RESULT --scene --preset --plot --pellet --coordinate --over -o
help "serve --help" serve --help -- --host --port --web --threads --queue --connections \
  --read-timeout --write-timeout --keep-alive --cache-mib --quiet --max-body --max-t-end \
  --max-events --max-steps --max-samples --deadline-ms --max-width --max-height --max-pixels \
  --max-pellets --max-limiters --max-plots --sweep-jobs --sweep-threads --sweep-queue --replica
help "serve -h" serve -h -- --port --replica
help "presets --help" presets --help -- presets
help "preset --help" preset --help -- NAME

status=0
"$vibro" > out.txt 2>&1 || status=$?
if ((status == 2)) && grep -q "simulate" out.txt; then pass "no command: the list, exit 2"; else
  fail "no command: the list, exit 2 (exit $status)"; fi

usage "an unknown option" --colour "is not an option of \`vibro sweep\` (see \`vibro sweep --help\`)" \
  -- sweep --preset impact-oscillator --colour red
usage "an unknown serve flag" --colour -- serve --colour red
usage "an unknown command" frobnicate -- frobnicate
usage "an extra positional argument" b.json -- simulate a.json b.json
usage "presets takes no arguments" extra -- presets extra
usage "--threads 0" --threads "must be an integer in [1, 1024]" \
  -- sweep --preset impact-oscillator --threads 0
usage "--threads not a number" --threads "must be an integer in [1, 1024]" \
  -- sweep --preset impact-oscillator --threads four
usage "--repeats 51" --repeats "must be an integer in [1, 50]" \
  -- work-precision --preset paper --repeats 51
usage "--coordinate" --coordinate "must be \"dphi\" or \"phi\"" \
  -- sweep --preset impact-oscillator --coordinate psi
usage "--pellet out of range" --pellet "must be a pellet index in 0..0" \
  -- sweep --preset impact-oscillator --pellet 3
usage "--plot unknown" --plot -- sweep --preset impact-oscillator --plot pie
usage "--resume without -o" --resume -- sweep --preset impact-oscillator --resume
usage "--t-end not a number" --t-end "must be a number" -- simulate --preset paper --t-end soon
usage "--t-end out of range: the scene's field" t_end -- simulate --preset paper --t-end -1
usage "--method unknown: the scene's field" solver.method -- simulate --preset paper --method rk4
usage "--deadline-ms 0" --deadline-ms "must be a positive number of milliseconds" \
  -- simulate --preset paper --deadline-ms 0
usage "--what" --what "must be \"events\" or \"trajectory\"" \
  -- simulate --preset paper --what everything -o run.csv
usage "--what with JSON" --what -- simulate --preset paper --what events
usage "a missing value" --max-width "needs a value" -- serve --max-width
usage "a missing value of -o" --output "needs a value" -- simulate --preset paper -o
usage "--port not a number" --port "must be an integer in [0, 65535]" -- serve --port http
usage "--port out of range" --port "must be an integer in [0, 65535]" -- serve --port 70000
usage "--max-t-end" --max-t-end "must be a number in [1, 1000000]" -- serve --max-t-end 0.5
usage "a flag given a value" --quiet "cannot take the value \"maybe\"" -- serve --quiet=maybe
usage "an unknown preset" preset -- simulate --preset nope
usage "no scene" scene -- simulate
usage "two scenes" scene -- simulate --preset paper a.json
usage "an unreadable scene" scene -- simulate missing.json
usage "render without -o" -o -- render --preset paper
usage "render to .gif" -o -- render --preset paper -o paper.gif
usage "preset without a name" preset -- preset
echo '{"model":{"R":0.5,"alpah0":0.1,"pellets":[{"m":1,"phi0":0}]},"t_end":1}' > typo.json
usage "a scene's unknown key" model.alpah0 -- simulate typo.json
# An orbit guess far past any angle once hung `vibro orbit` (issue 31): refused, naming it.
echo '{"model":{"R":0.5,"alpha0":0,"pellets":[{"m":0.1,"phi0":0.1,"F0":0.3,"Omega":5}],
  "limiters":[{"angle":0,"k":0.8}]},"t_end":20,
  "periodic_orbit":{"periods":1,"guess":[{"phi":1e17,"dphi":1}]}}' > far-guess.json
usage "an orbit guess of 1e17 rad" "periodic_orbit.guess[0].phi" \
  -- orbit far-guess.json --deadline-ms 500

# Runs: a scene on stdin with overrides, the last of a repeated option counting.
if "$vibro" preset paper | "$vibro" simulate - --t-end 0.5 --t-end 0.2 --method dopri5 \
    --rtol 1e-6 --no-check -o run.json && python3 -c '
import json; r = json.load(open("run.json")); assert r["stats"]["t_reached"] <= 0.2 + 1e-12, r["stats"]'
then pass "simulate - with overrides"; else fail "simulate - with overrides"; fi

# work-precision -o draws the diagram and prints where it went, not the table (some 400 lines).
if "$vibro" work-precision --preset paper --t-end 1 --repeats 1 -o wp.png > out.txt && python3 -c '
import json; lines = open("out.txt").read().splitlines(); assert len(lines) == 1, len(lines)
r = json.loads(lines[0]); assert r["image"] == "wp.png" and r["bytes"] > 1000, r'
then pass "work-precision -o prints where the diagram went"
else fail "work-precision -o prints where the diagram went"; head -5 out.txt; fi

# work-precision -o OUT.json writes the table the diagram drawn beside it comes from (one timing).
if "$vibro" work-precision --preset paper --t-end 1 --repeats 1 -o wp2.png -o wp.json > out.txt &&
  python3 -c '
import json; lines = [json.loads(l) for l in open("out.txt").read().splitlines()]
assert [l.get("image") or l.get("table") for l in lines] == ["wp2.png", "wp.json"], lines
t = json.load(open("wp.json")); assert t["reference"] and len(t["points"]) > 10, list(t)'
then pass "work-precision -o OUT.json writes the table beside the diagram"
else fail "work-precision -o OUT.json writes the table beside the diagram"; head -5 out.txt; fi

# A scene that cannot be read is named with the reason, by every command that reads one.
mkdir -p adir
for command in simulate render work-precision sweep orbit; do
  usage "$command of a directory" scene "adir is a directory, not a file" -- "$command" adir -o x.png
  usage "$command of a missing file" scene "nothing.json does not exist" -- "$command" nothing.json
done
if (($(id -u) != 0)); then  # root reads any file
  echo '{}' > secret.json && chmod 000 secret.json
  usage "an unreadable scene" scene "secret.json cannot be opened: Permission denied" \
    -- simulate secret.json
fi

# Output that cannot be written fails loudly, and the file it would replace stays whole. A file
# size limit (ulimit -f, in KiB, its signal ignored) fails a write as a full disk does.
limited() {  # limited KIB ARGS...: vibro ARGS with files limited to KIB
  local kib="$1"
  shift
  (trap '' XFSZ; ulimit -f "$kib"; exec "$vibro" "$@")
}
# wont_write NAME FILE KIB ARGS...: vibro ARGS exits 1 naming -o, FILE keeps its bytes and no
# temporary file is left beside it.
wont_write() {
  local name="$1" file="$2" kib="$3" status=0
  shift 3
  echo "the good result" > "$file"
  limited "$kib" "$@" > out.txt 2> err.txt || status=$?
  if ((status == 1)) && grep -q '"field":"-o"' err.txt && grep -q "cannot be written" err.txt \
      && [[ "$(cat "$file")" == "the good result" ]] && ! ls -A | grep -q '\.tmp-'; then
    pass "$name"; else fail "$name (exit $status)"; cat err.txt; ls -A; fi
}
wont_write "simulate -o on a full disk" run.json 1 simulate --preset paper -o run.json
wont_write "simulate -o CSV on a full disk" run.csv 1 simulate --preset paper -o run.csv
wont_write "render -o on a full disk" paper.png 1 render --preset paper --t-end 2 -o paper.png
wont_write "orbit -o on a full disk" orbit.json 1 orbit --preset impact-oscillator -o orbit.json
wont_write "work-precision -o on a full disk" wp.svg 1 work-precision --preset paper --t-end 1 \
  --repeats 1 -o wp.svg
status=0
"$vibro" simulate --preset paper --t-end 1 > /dev/full 2> err.txt || status=$?
if ((status == 1)) && grep -q '"field":"stdout"' err.txt; then pass "simulate > /dev/full fails"
else fail "simulate > /dev/full fails (exit $status)"; cat err.txt; fi
status=0
"$vibro" presets > /dev/full 2> err.txt || status=$?
if ((status == 1)); then pass "presets > /dev/full fails"; else fail "presets > /dev/full fails"; fi

# A sweep on a full disk stops once its checkpoint cannot be written, keeps the old output and
# the chains finished whole, and --resume completes it to the output of a run never stopped.
"$vibro" preset impact-oscillator | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["sweep"].update(count=12, continuation="none", transient=5, record=20)
json.dump(s, open("small.json", "w"))'
"$vibro" sweep small.json -o fresh.csv --threads 2 2> err.txt || cat err.txt
wont_write "sweep -o on a full disk" out.csv 8 sweep small.json -o out.csv --threads 2
if grep -q "chains it holds whole are kept" err.txt && [[ -s out.csv.partial ]]; then
  pass "the stopped sweep's checkpoint is kept"; else fail "the stopped sweep's checkpoint is kept"; fi
cp out.csv.partial whole.partial

# resume_refused NAME WHAT PYTHON: the checkpoint changed by PYTHON (on bytes b, its header line
# h and records from r) makes --resume exit 2 naming --resume with WHAT in its message.
resume_refused() {
  cp whole.partial out.csv.partial
  python3 -c "
b = bytearray(open('out.csv.partial', 'rb').read()); r = b.index(b'\n') + 1
$3
open('out.csv.partial', 'wb').write(b)"
  usage "$1" --resume -- sweep small.json -o out.csv --resume
  grep -q "$2" err.txt || { fail "$1: the message says $2"; cat err.txt; }
}
resume_refused "--resume refuses a flipped bit" "record 1 (at byte .*) fails its checksum" \
  "b[r + 40] ^= 1"
resume_refused "--resume refuses a relabelled chain" "fails its checksum" "b[r + 20] ^= 3"
resume_refused "--resume refuses another scene's checkpoint" "belongs to another scene" "b[r - 3] ^= 1"
resume_refused "--resume refuses a duplicated record" "which an earlier record holds" \
  "import struct; n = 8 + struct.unpack('=Q', bytes(b[r:r + 8]))[0] + 4; b += b[r:r + n]"
cp whole.partial out.csv.partial
if "$vibro" sweep small.json -o out.csv --resume --threads 2 2> err.txt && cmp -s out.csv fresh.csv \
    && [[ ! -e out.csv.partial ]]; then pass "--resume completes the stopped sweep"
else fail "--resume completes the stopped sweep"; cat err.txt; fi

# A disk that is really full, where a tmpfs may be mounted (root, outside most containers' CI).
mkdir -p small-disk
if mount -t tmpfs -o size=64k tmpfs small-disk 2> /dev/null; then
  disk="$work/small-disk"
  cp fresh.csv small-disk/out.csv
  head -c 100000 /dev/zero > small-disk/filler 2> /dev/null  # fills what is left
  status=0
  "$vibro" sweep small.json -o small-disk/out.csv 2> err.txt || status=$?
  if ((status == 1)) && grep -q "No space left on device" err.txt && cmp -s small-disk/out.csv fresh.csv \
      && [[ "$(ls -A small-disk)" == $'filler\nout.csv' ]]; then
    pass "sweep -o on a full tmpfs keeps the old output"
  else fail "sweep -o on a full tmpfs keeps the old output (exit $status)"; cat err.txt; ls -A small-disk; fi
  umount small-disk && disk=""
fi

# One run writes every -o given; `vibro plot` redraws a saved sweep or branch without running
# anything, as the command that ran it drew it.
if "$vibro" sweep small.json --threads 2 -o s.csv -o s.json -o s.png -o s.svg 2> err.txt \
    && [[ -s s.png && -s s.svg ]] && head -1 s.csv | grep -q '^model.pellets\[0\].Omega,value2,start,' \
    && python3 -c 'import json; assert "sweep" in json.load(open("s.json"))["scene"]'
then pass "sweep writes several outputs from one run"
else fail "sweep writes several outputs from one run"; cat err.txt; head -1 s.csv; fi
if "$vibro" plot s.json -o r.png -o r.pdf > out.txt 2> err.txt && cmp -s r.png s.png \
    && [[ -s r.pdf ]] && (($(wc -l < out.txt) == 2)) \
    && "$vibro" plot s.json --plot section --coordinate phi -o sec.png 2>> err.txt && [[ -s sec.png ]]
then pass "plot redraws a saved sweep, the same image"
else fail "plot redraws a saved sweep, the same image"; cat err.txt out.txt; fi
python3 -c '
import json; j = json.load(open("s.json")); del j["scene"]; json.dump(j, open("bare.json", "w"))'
usage "plot of a result that does not carry its scene" scene -- plot bare.json -o x.png
if "$vibro" plot bare.json --scene small.json -o bare.png > /dev/null 2> err.txt \
    && cmp -s bare.png s.png; then pass "plot with --scene"
else fail "plot with --scene"; cat err.txt; fi
usage "plot of a Lyapunov line the sweep did not compute" sweep.lyapunov \
  -- plot s.json --plot lyapunov -o x.png
usage "plot of what is no result" RESULT -- plot s.png -o x.png
usage "plot without -o" -o -- plot s.json
python3 -c '
import json; s = json.load(open("small.json"))
s["periodic_orbit"]["continuation"].update(to=6.0, max_points=30)
json.dump(s, open("branch.json", "w"))'
if "$vibro" orbit branch.json -o o.json -o o.png 2> err.txt && [[ -s o.png ]] \
    && "$vibro" plot o.json --over s.json -o o2.png > /dev/null 2>> err.txt && [[ -s o2.png ]]
then pass "orbit writes several outputs; plot redraws its branch over a saved sweep"
else fail "orbit writes several outputs; plot redraws its branch over a saved sweep"; cat err.txt; fi
if "$vibro" simulate --preset paper --t-end 2 -o run.json -o events.csv 2> err.txt && python3 -c '
import csv, json
events = json.load(open("run.json"))["events"]
rows = list(csv.DictReader(open("events.csv")))
assert len({r["event"] for r in rows}) == len(events), (len(rows), len(events))'
then pass "simulate writes JSON and CSV from one run"
else fail "simulate writes JSON and CSV from one run"; cat err.txt; fi
if "$vibro" render --preset paper --t-end 1 -o p.png -o p.svg > out.txt 2> err.txt && python3 -c '
import json; r = json.load(open("out.txt"))
assert [i["image"] for i in r["images"]] == ["p.png", "p.svg"] and "answer" in r, r'
then pass "render draws one run in several formats"
else fail "render draws one run in several formats"; cat err.txt out.txt; fi

# A trajectory at a uniform step: every pellet's state at t = 0, dt, ..., t_end, from its start.
if "$vibro" simulate --preset paper --t-end 2 --what trajectory --dt 0.01 -o u.csv 2> err.txt \
    && python3 -c '
import csv; rows = list(csv.DictReader(open("u.csv")))
assert list(rows[0]) == ["t", "pellet", "phi", "dphi"], rows[0]
assert len(rows) == 2 * 201, len(rows)
assert all(abs(float(r["t"]) - 0.01 * (k // 2)) < 1e-12 for k, r in enumerate(rows))
assert float(rows[0]["dphi"]) == 50 and float(rows[-1]["t"]) == 2'
then pass "simulate --dt samples the trajectory at a uniform step"
else fail "simulate --dt samples the trajectory at a uniform step"; cat err.txt; fi
usage "--dt 0" --dt -- simulate --preset paper --what trajectory --dt 0 -o u.csv
usage "--dt making too many samples" --dt -- simulate --preset paper --what trajectory --dt 1e-9 -o u.csv
usage "--dt without --what trajectory" --dt -- simulate --preset paper --dt 0.1 -o u.csv

# The serve flags reach the config: the limits and workers the server reports.
"$vibro" serve --port 0 --quiet --threads 3 --max-t-end 50 --deadline-ms 250 --max-pixels 1e6 \
  --cache-mib 8 > serve.out 2> serve.err &
server=$!
if python3 - << 'PY'; then pass "serve flags set the config"; else
import json, re, time, urllib.request
for _ in range(300):
    m = re.search(r"http://127\.0\.0\.1:(\d+)/", open("serve.out").read())
    if m:
        break
    time.sleep(0.1)
base = "http://127.0.0.1:%s" % m.group(1)
limits = json.load(urllib.request.urlopen(base + "/api/limits"))
health = json.load(urllib.request.urlopen(base + "/api/health"))
assert limits["t_end"] == 50 and limits["deadline_ms"] == 250, limits
assert limits["pixels"] == 1000000, limits
assert health["workers"] == 3, health
PY
  fail "serve flags set the config"; cat serve.out serve.err; fi

# The server draws a continuation's curves as `vibro orbit` does: over the regime map of the same
# two parameters, the sweep run in the orbit's job and counted in its progress.
kill "$server" 2> /dev/null && wait "$server" 2> /dev/null
curves="$root/docs/scenes/impact-oscillator-pd-curve.json"
"$vibro" orbit "$curves" -o cli-curves.png > /dev/null 2> err.txt || fail "vibro orbit draws the curves"
"$vibro" serve --port 0 --quiet > serve.out 2> serve.err &
server=$!
if python3 - "$curves" << 'PY'; then pass "the server draws the curves over the regime map as vibro orbit does"; else
import json, re, sys, time, urllib.request
for _ in range(300):
    m = re.search(r"http://127\.0\.0\.1:(\d+)/", open("serve.out").read())
    if m:
        break
    time.sleep(0.1)
base = "http://127.0.0.1:%s" % m.group(1)
post = urllib.request.Request(base + "/api/periodic-orbit", open(sys.argv[1], "rb").read(),
                              {"Content-Type": "application/json"})
job = json.load(urllib.request.urlopen(post))
assert job["progress"]["total"] == 1000 + 40 * 25, job  # the way along Ω, then the map's runs
for _ in range(3000):  # a hang fails after 300 s
    status = json.load(urllib.request.urlopen(base + "/api/jobs/" + job["id"]))
    if status["status"] not in ("queued", "running"):
        break
    time.sleep(0.1)
assert status["status"] == "done" and status["progress"]["done"] == 2000, status
png = urllib.request.urlopen(base + "/api/jobs/" + job["id"] + "/result?format=png").read()
assert png == open("cli-curves.png", "rb").read(), "the images differ"
PY
  fail "the server draws the curves over the regime map as vibro orbit does"; cat serve.err; fi

echo "$failures failed"
((failures == 0))
