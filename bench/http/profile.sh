#!/usr/bin/env bash
# Where an uncached PNG render's CPU goes in `vibro serve`: perf samples the server while wrk
# posts the paper scene (a t_end of its own per request, bench/http/uncached.lua), and the
# samples are split by the stage on their call stack (docs/PERFORMANCE.md, "The render path").
# Usage: bench/http/profile.sh [seconds, default 10]   (env: VIBRO, PORT; needs perf and wrk)
set -euo pipefail
cd "$(dirname "$0")/../.."

duration="${1:-10}"
vibro="${VIBRO:-build/vibro}"
port="${PORT:-18182}"
command -v perf > /dev/null || { echo "profile.sh: needs perf (apt-get install -y linux-perf)" >&2; exit 1; }
command -v wrk > /dev/null || { echo "profile.sh: needs wrk (apt-get install -y wrk)" >&2; exit 1; }

work="$(mktemp -d)"
trap 'kill "$server" 2> /dev/null; wait "$server" 2> /dev/null; rm -rf "$work"' EXIT
source bench/http/serve.sh
start_server

SCENE="$work/scene.json" PATH_AND_QUERY="/api/render?format=png" \
  wrk -t2 -c16 -d"$((duration + 2))s" -s bench/http/uncached.lua "$base" > /dev/null &
load=$!
sleep 1
# DWARF unwinding: Debian's cairo, pixman and libc keep no frame pointers.
perf record -q --call-graph dwarf -F 499 -p "$server" -o "$work/perf.data" -- sleep "$duration" \
  > /dev/null 2>&1
wait "$load"

# Each sample counts once, for the first stage found on its stack (innermost first).
perf script -i "$work/perf.data" -F comm,ip,sym 2> /dev/null | /usr/bin/python3 -c '
import re, sys
stages = [  # (stage, a pattern of a frame that marks it), most specific first
    # Frames of the encoder and of pixman too: DWARF unwinding stops inside some of them.
    ("PNG encoding", r"encode_png_argb32|zlib_image_rows|write_block|huffman_lengths|"
                     r"canonical_codes|rgb_row|rgb_quads|libdeflate_"),
    ("text (cairo glyphs)", r"cairo_show_text|cairo_text_extents|cairo_scaled_font|text_box|"
                            r"draw_text|pixman_composite_glyphs"),
    ("thinning", r"to_thinned_pixels|thin_polyline"),
    ("curves (cairo stroke)", r"stroke_polyline"),
    ("other drawing (cairo)", r"draw_figure|render_png|cairo_|pixman_"),
    ("simulation", r"vibro::simulate|Simulation::run"),
    ("scene parsing (JSON)", r"scene_from|nlohmann|parse"),
    ("response writing (HTTP)", r"httplib|write_response|send|writev"),
]
counts, total, stack = {}, 0, []
def flush():
    global total
    if not stack:
        return
    total += 1
    for name, pattern in stages:
        if any(re.search(pattern, f) for f in stack):
            counts[name] = counts.get(name, 0) + 1
            return
    counts["other (threads, kernel, allocation)"] = counts.get("other (threads, kernel, allocation)", 0) + 1
for line in sys.stdin:
    if not line.strip():
        flush(); stack = []
    elif line.startswith("\t"):
        stack.append(line.strip())
    else:
        flush(); stack = []
flush()
print("| stage | share of the server CPU |")
print("|---|---:|")
for name, n in sorted(counts.items(), key=lambda kv: -kv[1]):
    print("| %s | %.1f %% |" % (name, 100.0 * n / total))
print("\n%d samples" % total)
'
