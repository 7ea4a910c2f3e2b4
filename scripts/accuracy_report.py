#!/usr/bin/env python3
"""Writes docs/ACCURACY.md: work-precision tables and diagrams of the paper scene and the hard
cases, the error estimate against the true error, long runs, and the limits of the extremes.

Usage: python3 scripts/accuracy_report.py [path/to/vibro]   (default: build/vibro)
Every number in the page comes from this script's runs of `vibro`.
"""
import json
import math
import os
import platform
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VIBRO = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "vibro")
IMAGES = os.path.join(ROOT, "docs", "images")
METHODS = ["dopri5", "dop853", "radau5", "auto"]
DIAGRAMS = ["paper", "frictionless-elastic", "stiff-friction", "chatter"]
SWEPT = ["paper", "frictionless-elastic", "chatter", "stiff-friction", "tiny-radius",
         "high-frequency", "mass-ratio", "grazing", "loop", "plastic-limiter", "rest-in-cone"]


def run(args, stdin=None):
    out = subprocess.run([VIBRO] + args, input=stdin, capture_output=True, text=True, timeout=600)
    return out.returncode, out.stdout, out.stderr


def preset(name):
    return json.loads(run(["preset", name])[1])


def fmt(x, digits=2):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    return f"{x:.{digits}e}"


def work_precision(name):
    args = ["work-precision", "--preset", name, "--repeats", "3"]
    if name in DIAGRAMS:
        args += ["-o", os.path.join(IMAGES, f"wp-{name}.png")]
    code, out, err = run(args)
    if code != 0:
        raise SystemExit(f"work-precision {name} failed: {err}")
    return json.loads(out)


def wp_table(report):
    rows = {}
    for p in report["points"]:
        rows.setdefault(p["rtol"], {})[p["method"]] = p
    lines = ["| rtol | " + " | ".join(f"{m}: error / ms" for m in METHODS) + " |",
             "|---|" + "---|" * len(METHODS)]
    for rtol in sorted(rows, reverse=True):
        cells = []
        for m in METHODS:
            p = rows[rtol].get(m)
            if not p:
                cells.append("—")
                continue
            mark = "" if p["events_match"] else " ‡"
            cells.append(f"{fmt(p['error'])} / {p['median_ms']:.2f}{mark}")
        lines.append(f"| {rtol:.0e} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def estimate_table(reports):
    lines = ["| scene | reference | rtol | true error | estimate | ratio |", "|---|---|---|---|---|---|"]
    for name, report in reports.items():
        for p in report["points"]:
            if p["method"] != "auto" or p["rtol"] not in (1e-4, 1e-8, 1e-12):
                continue
            ratio = p["estimate"] / p["error"] if p["error"] and p["estimate"] else None
            lines.append(f"| {name} | {report['error_reference']} | {p['rtol']:.0e} | {fmt(p['error'])} | "
                         f"{fmt(p['estimate'])} | {fmt(ratio, 1) if ratio else '—'} |")
    return "\n".join(lines)


def best_methods(reports):
    lines = ["| scene | cheapest method reaching error ≤ 1e-6 | cheapest reaching ≤ 1e-9 |", "|---|---|---|"]
    for name, report in reports.items():
        cells = []
        for target in (1e-6, 1e-9):
            ok = [p for p in report["points"] if p["error"] is not None and p["error"] <= target and p["completed"]]
            if not ok:
                cells.append("none")
                continue
            best = min(ok, key=lambda p: p["median_ms"])
            auto = min((p for p in ok if p["method"] == "auto"), key=lambda p: p["median_ms"], default=None)
            ratio = f", auto {auto['median_ms'] / best['median_ms']:.2f}×" if auto else ", auto never"
            cells.append(f"{best['method']} ({best['median_ms']:.2f} ms{ratio})")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def simulate(scene, extra=()):
    code, out, err = run(["simulate", "-", *extra], stdin=json.dumps(scene))
    if code == 2:
        return {"error": json.loads(err)}
    return json.loads(out)


def long_runs():
    scene = {"model": {"R": 0.5, "alpha0": 0.05,
                       "pellets": [{"m": 0.2, "phi0": 0.0, "dphi0": 2.0, "F0": 1.2, "Omega": 3.3}],
                       "limiters": [{"angle": 0.35, "k": 0.6}, {"angle": -0.35, "k": 0.6}]},
             "t_end": 1000.0}
    lines = ["| rtol | events | limiter impacts | steps | wall ms | error estimate |", "|---|---|---|---|---|---|"]
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        r = simulate(scene, ["--rtol", str(rtol), "--atol", str(rtol * 1e-2)])
        s = r["stats"]
        lines.append(f"| {rtol:.0e} | {s['events']} | {r['summary']['limiter_impacts']} | {s['steps']} | "
                     f"{s['wall_ms']:.1f} | {fmt(s['error_estimate'])} |")
    return json.dumps(scene), "\n".join(lines)


def one_pellet(R=0.5, alpha0=0.05, dphi0=5.0, F0=0.0, Omega=0.0, m=0.2, limiters=None):
    return {"model": {"R": R, "alpha0": alpha0,
                      "pellets": [{"m": m, "phi0": 0.0, "dphi0": dphi0, "F0": F0, "Omega": Omega}],
                      "limiters": limiters if limiters is not None else [{"angle": 0.6, "k": 0.7}, {"angle": -0.6, "k": 0.7}]},
            "t_end": 2.0}


def extremes():
    cases = []
    for R in (1e-3, 1e-4, 1e-5, 1e-6):
        cases.append((f"R = {R:g} m", one_pellet(R=R, dphi0=5.0 / math.sqrt(R / 0.5))))
    for a in (1.0, 1.3, 1.5):
        cases.append((f"alpha0 = {a}", one_pellet(alpha0=a, dphi0=200.0)))
    for v in (1e3, 1e4, 1e5):
        cases.append((f"dphi0 = {v:g} rad/s (no limiters)", one_pellet(dphi0=v, limiters=[])))
        cases.append((f"dphi0 = {v:g} rad/s (limiters ±0.6)", one_pellet(dphi0=v)))
    for ratio in (1e4, 1e6, 1e8):
        sc = one_pellet()
        sc["model"]["pellets"] = [{"m": 1.0, "phi0": -0.3, "dphi0": 3.0},
                                  {"m": 1.0 / ratio, "phi0": 0.2, "dphi0": 0.0}]
        sc["model"]["limiters"] = [{"angle": 0.5, "k": 0.9}, {"angle": -1.0, "k": 0.9}]
        cases.append((f"mass ratio {ratio:g}", sc))
    for Om in (1e3, 1e4, 1e5, 1e6):
        sc = one_pellet(dphi0=0.0, F0=20.0, Omega=Om)
        sc["t_end"] = 0.5
        cases.append((f"Omega = {Om:g} rad/s, F0 = 20 N", sc))
    lines = ["| case | outcome | events | steps | wall ms | error estimate |", "|---|---|---|---|---|---|"]
    for label, scene in cases:
        r = simulate(scene, ["--deadline-ms", "10000"])
        if "error" in r:
            lines.append(f"| {label} | refused: `{r['error']['field']}` {r['error']['error']} | | | | |")
            continue
        s = r["stats"]
        outcome = s["termination"] + (f": {s['message']}" if s.get("message") else "")
        lines.append(f"| {label} | {outcome} | {s['events']} | {s['steps']} | {s['wall_ms']:.1f} | "
                     f"{fmt(s['error_estimate'])} |")
    return "\n".join(lines)


def main():
    os.makedirs(IMAGES, exist_ok=True)
    reports = {name: work_precision(name) for name in SWEPT}
    long_scene, long_table = long_runs()
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    out = [
        "# Accuracy: error against run time",
        "",
        "Made by `python3 scripts/accuracy_report.py` (after `bash scripts/setup.sh`); every number",
        f"below comes from that run, on {os.cpu_count()} cores of an {cpu} ({platform.system()}).",
        "Times are medians of 3 runs on a shared machine: read them as ratios, not absolutes.",
        "",
        "## What the error numbers mean",
        "",
        "- **The run's own estimate** (`stats.error_estimate`, in every result) is the larger of the",
        "  energy-balance defect `|E(t) − E(0) − W_force − W_friction − impact losses|` over the energy",
        "  scale, and the residual of the exact first integral of MODEL.md on unforced paper-law",
        "  intervals. Both vanish for the exact solution; both are measured at every event and at the end.",
        "- **The true error** of the work-precision sweeps (`vibro work-precision`) is measured against",
        "  what is exact where it applies — the first integral (unforced, paper law), the energy (no",
        "  friction, no forcing) — and otherwise against a reference run with another method at",
        "  rtol 1e-13: the largest of |Δt|/√(R/g) over the events, |Δφ| and √(R/g)|Δφ̇| at the end.",
        "  ‡ marks runs whose events part ways with the reference (their error is over the shared part).",
        "",
        "## Work-precision diagrams",
        "",
    ]
    for name in DIAGRAMS:
        out += [f"`vibro work-precision --preset {name} -o docs/images/wp-{name}.png`", "",
                f"![work-precision, {name}](images/wp-{name}.png)", ""]
    out += ["## Tables", ""]
    for name, report in reports.items():
        out += [f"### {name}", "", f"Error reference: {report['reference']}.", "", wp_table(report), ""]
    out += ["## Which method, and how close `auto` is", "", best_methods(reports), "",
            "## The estimate against the true error (method auto)", "",
            "Where the reference is exact (first integral, energy) the estimate is the true error. Against",
            "a reference run it measures the local consistency of the motion, not the drift of event",
            "times, and can be smaller than the true error in scenes where small differences grow.", "",
            estimate_table(reports), "",
            "## A long forced run", "",
            "One forced pellet between two limiters for t_end = 1000 s: the event count must not drift",
            "as the tolerance shrinks. Memory stays bounded: the run keeps events, not samples, unless",
            "asked.", "", "```json", long_scene, "```", "", long_table, "",
            "## The extremes", "",
            "One pellet (0.2 kg, R = 0.5 m, alpha0 = 0.05, limiters at ±0.6 rad, k = 0.7, t_end = 2 s)",
            "unless the row says otherwise; each run has a 10 s deadline. A case beyond what the engine",
            "can do ends with a clear termination and message, never NaN or a hang.", "",
            extremes(), ""]
    with open(os.path.join(ROOT, "docs", "ACCURACY.md"), "w") as f:
        f.write("\n".join(out))
    print("accuracy: docs/ACCURACY.md written")


if __name__ == "__main__":
    main()
