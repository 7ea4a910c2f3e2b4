#!/usr/bin/env python3
"""The impact-oscillator sweep's accuracy and time, for one or more builds of vibro side by side.

Usage: /usr/bin/python3 bench/sweep_accuracy.py VIBRO [VIBRO...] [--rtols 1e-9,1e-10]
                                                [--method taylor] [--rounds 5] [--core 1]

Runs the preset's 1,000-value sweep (50 transient and 20 recorded periods, no continuation, the
check off, atol = rtol/100) with `vibro sweep --threads 1`, pinned to one core, each build and
tolerance in turn `--rounds` times. Prints per build and tolerance the median wall time of the
sweep's own clock, its runs per second, and the median distance of its stroboscopic points from
a reference run (the first build, Taylor at rtol 1e-14): max(|Δφ|, |Δφ̇|·√(R/g)), point by point,
with the number of values whose every point lies within 1e-10.
"""
import argparse
import json
import math
import statistics
import subprocess


def scene(vibro, method, rtol):
    s = json.loads(subprocess.run([vibro, "preset", "impact-oscillator"], capture_output=True,
                                  text=True, check=True).stdout)
    s["sweep"].update(count=1000, transient=50, record=20, continuation="none")
    s["solver"] = {"method": method, "rtol": rtol, "atol": rtol / 100, "check": False}
    return s


def sweep(vibro, s, core):
    out = subprocess.run(["taskset", "-c", str(core), vibro, "sweep", "-", "--threads", "1"],
                         input=json.dumps(s), capture_output=True, text=True, check=True).stdout
    result = json.loads(out)
    by_value = {}
    p = result["points"]
    for v, phi, dphi in zip(p["value"], p["phi"], p["dphi"]):
        by_value.setdefault(v, []).append((phi, dphi))
    return by_value, result["stats"]["wall_ms"]


def distances(points, reference, speed):
    """Every point's distance from the reference's, and per value the largest."""
    each, worst = [], []
    for v, ref in reference.items():
        d = [max(abs(a[0] - b[0]), abs(a[1] - b[1]) * speed) for a, b in zip(points[v], ref)]
        each += d
        worst.append(max(d) if d else 0.0)
    return each, worst


def main():
    a = argparse.ArgumentParser()
    a.add_argument("vibro", nargs="+")
    a.add_argument("--rtols", default="1e-9,1e-10")
    a.add_argument("--method", default="taylor")
    a.add_argument("--rounds", type=int, default=5)
    a.add_argument("--core", type=int, default=1)
    o = a.parse_args()
    rtols = [float(r) for r in o.rtols.split(",")]
    ref_scene = scene(o.vibro[0], "taylor", 1e-14)
    speed = math.sqrt(ref_scene["model"]["R"] / 9.81)
    reference, _ = sweep(o.vibro[0], ref_scene, o.core)
    times, errors = {}, {}
    for _ in range(o.rounds):
        for vibro in o.vibro:
            for rtol in rtols:
                points, ms = sweep(vibro, scene(vibro, o.method, rtol), o.core)
                times.setdefault((vibro, rtol), []).append(ms)
                errors[(vibro, rtol)] = distances(points, reference, speed)
    print("| vibro | rtol | median ms | runs/s | median distance | values within 1e-10 |")
    print("|---|---|---:|---:|---:|---:|")
    for vibro in o.vibro:
        for rtol in rtols:
            ms = statistics.median(times[(vibro, rtol)])
            each, worst = errors[(vibro, rtol)]
            print(f"| {vibro} | {rtol:g} | {ms:.0f} | {1e6 / ms:.0f} | "
                  f"{statistics.median(each):.3g} | {sum(w <= 1e-10 for w in worst)} |")


if __name__ == "__main__":
    main()
