#!/usr/bin/env python3
"""Peak resident memory of a sweep against the length of its runs (issue 10: memory grows with
the points kept, not with the runs' lengths).

Usage: python3 bench/sweep_memory.py [--vibro build/vibro] [--values 20]
Runs the impact-oscillator preset's sweep over N values of Omega (no continuation, one thread),
recording 20 periods each after transients of 20 to 20,000 periods (up to ~140,000 impacts per
run), and prints each sweep's section points, wall time and peak resident memory.
"""
import argparse
import json
import os
import resource
import subprocess
import tempfile
import time


def peak_of(cmd):
    """Runs cmd and returns (wall seconds, its peak resident memory in MB)."""
    start = time.monotonic()
    pid = os.fork()
    if pid == 0:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            os.dup2(null.fileno(), 2)
        os.execv(cmd[0], cmd)
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{' '.join(cmd)} failed")
    return time.monotonic() - start, usage.ru_maxrss / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--vibro", default="build/vibro")
    ap.add_argument("--values", type=int, default=20)
    args = ap.parse_args()
    scene = json.loads(subprocess.run([args.vibro, "preset", "impact-oscillator"],
                                      capture_output=True, text=True, check=True).stdout)
    print(f"{'transient':>9} {'record':>6} {'points':>7} {'wall s':>7} {'peak MB':>8}")
    with tempfile.TemporaryDirectory() as tmp:
        for transient in (20, 200, 2000, 20000):
            scene["sweep"].update(count=args.values, transient=transient, record=20,
                                  continuation="none", initial_states=1)
            path = os.path.join(tmp, f"t{transient}.json")
            out = os.path.join(tmp, f"t{transient}.csv")
            with open(path, "w") as f:
                json.dump(scene, f)
            wall, peak = peak_of([args.vibro, "sweep", path, "-o", out, "--threads", "1"])
            with open(out) as f:
                points = sum(1 for _ in f) - 1
            print(f"{transient:>9} {20:>6} {points:>7} {wall:>7.2f} {peak:>8.1f}")


if __name__ == "__main__":
    main()
