#!/usr/bin/env python3
"""Compares two sets of Google Benchmark results, benchmark by benchmark: the medians of each and
their ratio (after / before), and flags any benchmark more than --slower (5 %) slower.

    python3 bench/compare.py BEFORE_DIR AFTER_DIR [--slower 0.05]

Each directory holds the *.json that `--benchmark_out` wrote with --benchmark_repetitions (the
aggregates' "median" rows are read; without them, the mean of the runs).
"""
import argparse
import json
import os
import statistics
import sys


def medians(directory, field):
    out = {}
    for name in sorted(os.listdir(directory)):
        if not name.endswith(".json"):
            continue
        runs = {}
        for b in json.load(open(os.path.join(directory, name)))["benchmarks"]:
            base = b.get("run_name", b["name"])
            if b.get("aggregate_name") == "median":
                out[(name[:-5], base)] = b[field]
            elif b.get("run_type", "iteration") == "iteration":
                runs.setdefault(base, []).append(b[field])
        for base, times in runs.items():
            out.setdefault((name[:-5], base), statistics.median(times))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--slower", type=float, default=0.05)
    ap.add_argument("--time", choices=["real", "cpu"], default="real",
                    help="cpu: the time the benchmark's thread ran, less touched by other load")
    a = ap.parse_args()
    field = a.time + "_time"
    before, after = medians(a.before, field), medians(a.after, field)
    print("| benchmark | before | after | after / before |")
    print("|---|---:|---:|---:|")
    slower = []
    for key in sorted(before.keys() & after.keys()):
        r = after[key] / before[key]
        flag = " **slower**" if r > 1.0 + a.slower else ""
        if flag:
            slower.append(key)
        print(f"| {key[0]}: {key[1]} | {before[key]:.4g} | {after[key]:.4g} | {r:.3f}{flag} |")
    print(f"\n{len(slower)} of {len(before.keys() & after.keys())} more than {a.slower:.0%} slower")
    return 1 if slower else 0


if __name__ == "__main__":
    sys.exit(main())
