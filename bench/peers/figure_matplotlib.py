#!/usr/bin/env python3
"""The paper figure drawn by matplotlib (Agg) from vibro's own run: what a researcher would
script today. Two phase portraits (φ, φ̇) and φ(t) of both pellets, 1200×800 px, axis labels,
grids, the event markers; the run's trajectory points, every branch a line.

Usage: /usr/bin/python3 bench/peers/figure_matplotlib.py [--vibro build/vibro] [--repeats N]
       [--out FILE.json] [--png FILE.png]
Times only the drawing and the PNG encoding (figure creation to savefig into memory), median of
N repeats, CPU time of this process; the simulation is vibro's, run once beforehand. Prints and
writes {"median_ms", "repeats", "bytes", "points"}.
"""
import argparse
import io
import json
import statistics
import subprocess
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def run_paper(vibro):
    out = subprocess.run([vibro, "simulate", "--preset", "paper", "--trajectories"],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def draw(run):
    fig = plt.figure(figsize=(12, 8), dpi=100)
    grid = fig.add_gridspec(2, 2)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for pellet in (0, 1):
        ax = fig.add_subplot(grid[0, pellet])
        for k, b in enumerate(run["trajectories"][pellet]["branches"]):
            ax.plot(b["phi"], b["dphi"], color=colours[k % len(colours)], linewidth=1.5)
        for e in run["events"]:
            if pellet in e.get("pellets", []) and "dphi_before" in e:
                marker = "ko" if e["kind"] == "limiter" else "kD"
                ax.plot(e["phi"], e["dphi_before"][e["pellets"].index(pellet)], marker,
                        markersize=4, markerfacecolor="white" if marker == "kD" else "black")
        ax.set_xlabel("φ [rad]")
        ax.set_ylabel("φ̇ [rad/s]")
        ax.set_title(f"Phase portrait, pellet {pellet + 1}")
        ax.grid(True, color="0.9")
    ax = fig.add_subplot(grid[1, :])
    for pellet in (0, 1):
        for b in run["trajectories"][pellet]["branches"]:
            ax.plot(b["t"], b["phi"], color=colours[pellet], linewidth=1.5)
    for e in run["events"]:
        ax.plot(e["t"], -2.0, "ko" if e["kind"] == "limiter" else "kD", markersize=4)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("φ [rad]")
    ax.set_title("φ(t), pellets 1, 2")
    ax.grid(True, color="0.9")
    fig.tight_layout()
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    return buffer.getvalue()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--vibro", default="build/vibro")
    p.add_argument("--repeats", type=int, default=15)
    p.add_argument("--out")
    p.add_argument("--png")
    a = p.parse_args()
    run = run_paper(a.vibro)
    draw(run)  # warm-up: fonts, caches
    times = []
    png = b""
    for _ in range(a.repeats):
        start = time.process_time()
        png = draw(run)
        times.append((time.process_time() - start) * 1e3)
    points = sum(len(b["t"]) for tr in run["trajectories"] for b in tr["branches"])
    result = {"median_ms": statistics.median(times), "repeats": a.repeats, "bytes": len(png),
              "points": points}
    if a.png:
        with open(a.png, "wb") as f:
            f.write(png)
    print(json.dumps(result))
    if a.out:
        with open(a.out, "w") as f:
            json.dump(result, f)


if __name__ == "__main__":
    main()
