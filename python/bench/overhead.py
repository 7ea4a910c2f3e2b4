"""What calling the engine from Python costs (issue 35, "Speed"; docs/PERFORMANCE.md).

1. vibro.simulate on a preset, reading what a user reads of it (run.events, run.summary,
   run.stats, run.warnings: each is made when first read, so each is read here), against the same
   simulate(model, options) called from C++ (python_engine_call, python/bench/engine_call.cpp,
   built with -DVIBRO_BUILD_BENCH=ON): the difference is the call's overhead (the dict read as a
   scene, the result made into Python values), given as a share of the run. Median CPU times of
   the calling thread (on a shared machine wall time measures the other processes), the two
   measured in turn, the least disturbed round kept.
2. vibro.sweep against `vibro sweep` of the same scene on the same threads: the sweeps' own wall
   clock (stats.wall_ms) and the whole command or call.

Usage: /usr/bin/python3 python/bench/overhead.py [BUILD_DIR] [THREADS] [ENGINE_CALL]
(default build, 2, BUILD_DIR/python/python_engine_call)
Takes the best of several repetitions: on a shared machine the least disturbed one.

/usr/bin/python3 python/bench/overhead.py BUILD_DIR --calls N [PRESET] makes only N + 1 such calls
(the first a warm-up, as python_engine_call's), for a count of instructions or allocations by
python/bench/overhead_counts.sh, which is deterministic where times are not.
"""

import json
import pathlib
import statistics
import subprocess
import sys
import time

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
calls_only = len(sys.argv) > 3 and sys.argv[2] == "--calls"
threads = int(sys.argv[2]) if len(sys.argv) > 2 and not calls_only else 2
engine_call = pathlib.Path(sys.argv[3] if len(sys.argv) > 3 and not calls_only else build / "python" / "python_engine_call")
sys.path.insert(0, str(build / "python"))
import vibro  # noqa: E402


def call(scene):
    run = vibro.simulate(scene)
    run.events, run.summary, run.stats, run.warnings  # what a caller reads: arrays and Python values
    return run


def python_call_ms(scene, repeats):
    times = []
    for _ in range(repeats):
        start = time.thread_time()
        run = call(scene)  # noqa: F841 (kept, as a caller keeps it, until the next call)
        times.append((time.thread_time() - start) * 1e3)
    return statistics.median(times)


def engine_call_ms(name, repeats):
    out = subprocess.run([str(engine_call), name, str(repeats)], capture_output=True, text=True, check=True)
    return float(out.stdout)


def simulate_overhead(name, repeats=200, rounds=5):
    scene = vibro.preset(name)
    vibro.simulate(scene)  # warm, as the C++ side is
    best = None
    for _ in range(rounds):
        engine = engine_call_ms(name, repeats)
        call = python_call_ms(scene, repeats)
        if best is None or call + engine < sum(best):
            best = (call, engine)
    call, engine = best
    print(f"simulate {name}: vibro.simulate {call:.3f} ms, the engine from C++ {engine:.3f} ms: "
          f"overhead {call - engine:.3f} ms = {100 * (call - engine) / engine:.1f} % of the run")


def sweep_against_cli(repeats=3):
    scene = vibro.preset("impact-oscillator")
    scene["sweep"]["count"] = 100
    path = pathlib.Path("/tmp/vibro_bench_sweep.json")
    path.write_text(json.dumps(scene))
    py, cli = [], []
    for _ in range(repeats):
        start = time.perf_counter()
        result = vibro.sweep(scene, threads=threads)
        result.points
        py.append(((time.perf_counter() - start) * 1e3, result.stats["wall_ms"]))
        start = time.perf_counter()
        out = subprocess.run([str(build / "vibro"), "sweep", str(path), "--threads", str(threads)],
                             capture_output=True, text=True, check=True).stdout
        cli.append(((time.perf_counter() - start) * 1e3, json.loads(out)["stats"]["wall_ms"]))
    (pt, pw), (ct, cw) = min(py), min(cli)
    print(f"sweep impact-oscillator, 200 runs on {threads} threads: vibro.sweep {pt:.0f} ms "
          f"(sweep {pw:.0f} ms), vibro sweep {ct:.0f} ms (sweep {cw:.0f} ms)")


if calls_only:
    scene = vibro.preset(sys.argv[4] if len(sys.argv) > 4 else "paper")
    for _ in range(int(sys.argv[3]) + 1):
        run = call(scene)
else:
    simulate_overhead("paper")
    simulate_overhead("paper-fig6")
    sweep_against_cli()
