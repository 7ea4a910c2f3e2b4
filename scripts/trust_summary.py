#!/usr/bin/env python3
"""The pooled figures of several trust_scan runs (docs/ACCURACY.md's passage on seeds 1-32).

Usage: python3 scripts/trust_summary.py runs-1.csv runs-2.csv ...
  each written by `build/tests/differential/trust_scan --count 1000 --seed S --jobs 2 --out FILE`.

Prints the scenes and runs, the share trusted to their end, the median estimate / true error
(over the runs whose true error is above round-off, as trust_scan's table), DOP853's at rtol 1e-6,
the runs whose estimate falls ten times short of a true error above 1 % of what the tolerance
asks, the runs that vouched for wrong events, the runs with a true error above what their
tolerance asks, and the median check cost per method.
"""
import csv
import statistics
import sys


def main():
    rows = []
    scenes = 0
    for path in sys.argv[1:]:
        with open(path) as f:
            mine = list(csv.DictReader(f))
        scenes += len({r["scene"] for r in mine})
        rows += mine
    if not rows:
        raise SystemExit("no runs")
    num = lambda r, k: float(r[k])
    judged = [r for r in rows if r["missed"] == "0" and num(r, "truth") > 1e-14]
    ratio = lambda r: num(r, "estimate") / num(r, "truth")
    short = sum(ratio(r) < 0.1 and num(r, "truth") > 0.01 * num(r, "asked") for r in judged)
    dop853_loose = [ratio(r) for r in judged if r["method"] == "dop853" and float(r["rtol"]) == 1e-6]
    print(f"scenes {scenes:,}, runs {len(rows):,} ({len(rows) / scenes:.2f} a scene)")
    print(f"trusted to their end: {100.0 * sum(r['trusted_to_end'] == '1' for r in rows) / len(rows):.2f} %")
    print(f"median estimate / true error: {statistics.median(ratio(r) for r in judged):.2f}")
    print(f"DOP853 at rtol 1e-6, median estimate / true error: {statistics.median(dop853_loose):.0f}")
    print(f"estimates ten times short of a true error above 1 % of what is asked: {short}")
    print(f"runs that vouched for wrong events: {sum(r['missed'] != '0' for r in rows)}")
    print(f"true error above what the tolerance asks: "
          f"{sum(num(r, 'truth') > num(r, 'asked') for r in rows):,}")
    for method in dict.fromkeys(r["method"] for r in rows):
        cost = [num(r, "check_ratio") for r in rows if r["method"] == method and num(r, "check_ratio") > 0]
        print(f"check cost, median, {method}: {statistics.median(cost):.2f}x")


if __name__ == "__main__":
    main()
