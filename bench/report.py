#!/usr/bin/env python3
"""Turns the Google Benchmark JSON of bench/run.sh into the markdown tables of PERFORMANCE.md.

Usage: python3 bench/report.py build-bench/results
Every figure is the median over the repetitions; ratios divide medians of the same run.
The machine is shared: wall time includes preemption by other processes on the pinned core, so
the single-threaded comparisons (overhead multiples, matched-error ratios) use the median CPU
time of the benchmark thread; the engine's targets are judged on wall time.
"""
import json
import math
import os
import sys

VIBRO = ["dopri5", "dop853", "radau5", "auto"]
LEVELS = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]
UNIT_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def medians(path):
    """run_name -> median entry, with real_time and cpu_time in ms."""
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        if b.get("error_occurred"):
            out[b["run_name"]] = dict(b, skipped=b.get("error_message", "error"))
            continue
        scale = UNIT_MS[b["time_unit"]]
        out[b["run_name"]] = dict(b, real_ms=b["real_time"] * scale, cpu_ms=b["cpu_time"] * scale)
    return out


def fmt_ms(x):
    return f"{x:.3g}" if x < 100 else f"{x:.0f}"


def engine_table(m):
    targets = {"BM_PaperSimulatePng": 20.0, "BM_PaperSimulateSvg": 10.0, "BM_Cylinder1024Png": 150.0}
    print("| benchmark | median wall (ms) | median CPU (ms) | steps | target | met |")
    print("|---|---:|---:|---:|---:|---|")
    for name, b in m.items():
        if "skipped" in b:
            print(f"| {name} | skipped: {b['skipped']} | | | | |")
            continue
        t = targets.get(name)
        met = "" if t is None else ("yes" if b["real_ms"] < t else "**no**")
        target = "" if t is None else f"< {t:g} ms"
        print(f"| {name} | {fmt_ms(b['real_ms'])} | {fmt_ms(b['cpu_ms'])} | "
              f"{b.get('steps', 0):.0f} | {target} | {met} |")


def matplotlib_row(engine, path):
    """vibro's simulate + PNG of the paper figure against matplotlib drawing the same run."""
    if not os.path.exists(path) or "BM_PaperSimulatePng" not in engine:
        return
    with open(path) as f:
        mpl = json.load(f)
    ours = engine["BM_PaperSimulatePng"]["cpu_ms"]
    ratio = mpl["median_ms"] / ours
    print("\n| paper figure, 1200×800 PNG | CPU (ms) | bytes |")
    print("|---|---:|---:|")
    print(f"| vibro: simulate + draw + encode | {fmt_ms(ours)} | "
          f"{engine['BM_PaperSimulatePng'].get('bytes', 0):.0f} |")
    print(f"| matplotlib (Agg): draw + encode the same run's {mpl['points']} points | "
          f"{fmt_ms(mpl['median_ms'])} | {mpl['bytes']} |")
    print(f"\nvibro is {ratio:.0f}× faster (target ≥ 20×: {'met' if ratio >= 20 else '**not met**'}).")


def png_table(m):
    print("| encoder (paper figure's pixels) | median CPU (ms) | bytes |")
    print("|---|---:|---:|")
    for name, b in m.items():
        if "skipped" not in b:
            print(f"| {name} | {b['cpu_ms']:.2f} | {b.get('bytes', 0):.0f} |")


def overhead_table(m):
    print("| scene | method | run, CPU (ms) | rhs evals | bare rhs (ns) | rhs-only time (ms) "
          "| run / rhs-only | target < 2× |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for scene in ["paper", "forced"]:
        bare = m.get(f"BM_BareRhs_{scene}")
        if not bare:
            continue
        bare_ns = bare["cpu_ms"] * 1e6
        for method in VIBRO:
            b = m.get(f"BM_Run_{scene}/{method}")
            if not b:
                continue
            rhs_ms = b["rhs_evals"] * bare_ns * 1e-6
            multiple = b["cpu_ms"] / rhs_ms
            met = "yes" if multiple < 2.0 else "**no**"
            print(f"| {scene} | {method} | {fmt_ms(b['cpu_ms'])} | {b['rhs_evals']:.0f} | "
                  f"{bare_ns:.1f} | {fmt_ms(rhs_ms)} | {multiple:.2f}× | {met} |")


def frontier(points):
    """(error, ms) points -> the lower envelope, sorted by error: time never rises as the
    error allowed grows (a tighter run that is also faster dominates)."""
    pts = sorted(p for p in points if p[0] > 0)
    env = []
    for e, t in pts:
        if env and t >= env[-1][1]:
            continue
        env.append((e, t))
    return env


def time_at(env, level):
    """Time to reach error <= level, interpolated in log-log between the frontier's points;
    None outside the measured range (no extrapolation)."""
    if not env or level < env[0][0]:
        return None
    for (e0, t0), (e1, t1) in zip(env, env[1:]):
        if e0 <= level <= e1:
            w = (math.log(level) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t1) - math.log(t0)))
    # Beyond the loosest point: the loosest run already meets the level.
    return env[-1][1]


def work_precision(m, prefix):
    """scene -> solver -> [(rtol, entry)]"""
    table = {}
    for name, b in m.items():
        if not name.startswith(prefix):
            continue
        _, scene, solver, tol = name.split("/")
        table.setdefault(scene, {}).setdefault(solver, []).append((float(tol.split(":")[1]), b))
    return table


def work_precision_tables(m, prefix, title):
    for scene, solvers in work_precision(m, prefix).items():
        print(f"\n#### {title}: {scene}\n")
        print("| solver | rtol | error | impacts (ref) | same impacts | steps | rhs evals "
              "| wall (ms) | CPU (ms) |")
        print("|---|---:|---:|---:|---|---:|---:|---:|---:|")
        for solver, rows in solvers.items():
            for rtol, b in sorted(rows, key=lambda r: -r[0]):
                if "skipped" in b:
                    print(f"| {solver} | {rtol:.0e} | failed: {b['skipped']} | | | | | | |")
                    continue
                same = "yes" if b["same_impacts"] >= 1 else "**no**"
                print(f"| {solver} | {rtol:.0e} | {b['error']:.2e} | {b['impacts']:.0f} "
                      f"({b['reference_impacts']:.0f}) | {same} | {b['steps']:.0f} | "
                      f"{b['rhs_evals']:.0f} | {fmt_ms(b['real_ms'])} | {fmt_ms(b['cpu_ms'])} |")
        matched_table(solvers)


def matched_table(solvers):
    env = {}
    for solver, rows in solvers.items():
        env[solver] = frontier([(b["error"], b["cpu_ms"]) for _, b in rows
                                if "skipped" not in b and b["same_impacts"] >= 1])
    peers = [s for s in env if s not in VIBRO]
    names = list(env)
    print("\nCPU time (ms) to reach each error level, interpolated in log-log on each solver's "
          "frontier (runs that missed or added impacts excluded); ratio = vibro's best / the "
          "fastest peer's (< 1: vibro faster).\n")
    print("| error ≤ | " + " | ".join(names) + " | vibro best / peer best | auto / peer best |")
    print("|---" * (len(names) + 3) + "|")
    for level in LEVELS:
        times = {s: time_at(env[s], level) for s in names}
        if all(t is None for t in times.values()):
            continue
        cells = [("—" if times[s] is None else fmt_ms(times[s])) for s in names]
        vib = [times[s] for s in VIBRO if times.get(s) is not None]
        peer = [times[s] for s in peers if times[s] is not None]
        best = f"{min(vib) / min(peer):.2f}" if vib and peer else "—"
        auto = (f"{times['auto'] / min(peer):.2f}"
                if times.get("auto") is not None and peer else "—")
        print(f"| {level:.0e} | " + " | ".join(cells) + f" | {best} | {auto} |")


def event_peer_table(m):
    print("| solver | rtol | impacts (vibro ref) | max Δt, first 50 (s) | max Δt, all (s) "
          "| same count | steps | rhs evals | wall (ms) | CPU (ms) |")
    print("|---|---:|---:|---:|---:|---|---:|---:|---:|---:|")
    for name, b in m.items():
        parts = name.split("/")
        if "skipped" in b:
            print(f"| {parts[1]} | {parts[2]} | failed: {b['skipped']} | | | | | | | |")
            continue
        same = "yes" if b["same_impacts"] >= 1 else "**no**"
        print(f"| {parts[1]} | {parts[2].split(':')[1]} | {b['impacts']:.0f} "
              f"({b['reference_impacts']:.0f}) | {b['event_time_error']:.2e} | "
              f"{b['all_impacts_error']:.2e} | {same} | {b['steps']:.0f} | {b['rhs_evals']:.0f} | "
              f"{fmt_ms(b['real_ms'])} | {fmt_ms(b['cpu_ms'])} |")


def trust_table(m):
    print("| preset | events | unchecked (ms) | checked (ms) | checked / unchecked |")
    print("|---|---:|---:|---:|---:|")
    ratios = []
    for name, b in m.items():
        parts = name.split("/")
        if len(parts) != 3 or parts[2] != "unchecked" or "skipped" in b:
            continue
        c = m.get(f"Trust/{parts[1]}/checked")
        if not c or "skipped" in c:
            continue
        r = c["cpu_ms"] / b["cpu_ms"]
        ratios.append(r)
        print(f"| {parts[1]} | {b.get('events', 0):.0f} | {fmt_ms(b['cpu_ms'])} | "
              f"{fmt_ms(c['cpu_ms'])} | {r:.2f} |")
    if ratios:
        ratios.sort()
        print(f"\nMedian ratio {ratios[len(ratios) // 2]:.2f}, largest {ratios[-1]:.2f} "
              f"(CPU time of the benchmark thread).")


def method_table(m):
    """auto against the fastest single method, per preset and tolerance (wall time)."""
    rows = {}
    for name, b in m.items():
        parts = name.split("/")
        if len(parts) != 4 or parts[0] != "Method" or "skipped" in b:
            continue
        rows.setdefault((parts[1], parts[3]), {})[parts[2]] = b["real_ms"]
    print("| preset | rtol | dopri5 | dop853 | radau5 | auto (ms) | auto / fastest | within 1.2× |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    worst = 0.0
    for (preset, rtol), t in rows.items():
        single = [t[k] for k in ("dopri5", "dop853", "radau5") if k in t]
        if not single or "auto" not in t:
            continue
        r = t["auto"] / min(single)
        worst = max(worst, r)
        cells = " | ".join(fmt_ms(t[k]) if k in t else "—" for k in ("dopri5", "dop853", "radau5"))
        print(f"| {preset} | {rtol.split(':')[1]} | {cells} | {fmt_ms(t['auto'])} | {r:.2f} | "
              f"{'yes' if r <= 1.2 else '**no**'} |")
    print(f"\nLargest auto / fastest: {worst:.2f}.")


def main():
    results = sys.argv[1] if len(sys.argv) > 1 else "build-bench/results"
    print("### Engine (paper scene, 1200×800; 3-D panel 1024×1024)\n")
    engine = medians(os.path.join(results, "engine_bench.json"))
    engine_table(engine)
    matplotlib_row(engine, os.path.join(results, "matplotlib.json"))
    png = medians(os.path.join(results, "png_bench.json"))
    if png:
        print("\n### PNG encoders\n")
        png_table(png)
    print("\n### Cost per step relative to the right-hand side\n")
    overhead_table(medians(os.path.join(results, "overhead_bench.json")))
    print("\n### Work-precision, integrators behind vibro's driver (same events)")
    work_precision_tables(medians(os.path.join(results, "work_precision_bench.json")),
                          "WorkPrecision/", "Work-precision")
    mb = medians(os.path.join(results, "method_bench.json"))
    if mb:
        print("\n### auto against each method, every preset (median wall time)\n")
        method_table(mb)
    tr = medians(os.path.join(results, "trust_bench.json"))
    if tr:
        print("\n### The trust check: each preset with and without it\n")
        trust_table(tr)
    ev = medians(os.path.join(results, "event_peer_bench.json"))
    if ev:
        print("\n### Peers with their own event location (forced pellet between two limiters)\n")
        event_peer_table(ev)


if __name__ == "__main__":
    main()
