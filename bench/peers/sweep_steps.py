#!/usr/bin/env python3
"""Where the sweep comparison's time goes: one run of the impact-oscillator sweep (Omega = 7,
70 forcing periods) by SciPy's solve_ivp (DOP853, a terminal event per impact, restarted after
each) and by vibro (DOP853, the check off), per tolerance: steps, right-hand sides, and time per
step. Equal step counts leave the ratio of the two to the cost of a step.

Usage: /usr/bin/python3 bench/peers/sweep_steps.py [--vibro build/vibro] [--rtols 1e-6,...]
"""
import argparse
import json
import math
import os
import subprocess
import time

from scipy.integrate import solve_ivp

from sweep_scipy import impact_oscillator

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def scipy_run(scene, Omega, t_end, rtol):
    p = scene["model"]["pellets"][0]
    rhs, strike, k = impact_oscillator(scene, Omega)
    t, y, steps, nfev = 0.0, [p["phi0"], p["dphi0"]], 0, 0
    started = time.perf_counter()
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=rtol, atol=rtol * 1e-3,
                        events=strike)
        steps += len(sol.t) - 1
        nfev += sol.nfev
        if sol.status != 1 or abs(sol.y_events[0][0][1]) * k <= 1e-9:
            break
        t, y = sol.t_events[0][0], [0.0, -k * sol.y_events[0][0][1]]
    return steps, nfev, time.perf_counter() - started


def vibro_run(vibro, scene, Omega, t_end, rtol):
    s = dict(scene)
    s.pop("sweep", None)
    s["model"] = json.loads(json.dumps(scene["model"]))
    s["model"]["pellets"][0]["Omega"] = Omega
    s["t_end"] = t_end
    s["solver"] = {"method": "dop853", "rtol": rtol, "atol": rtol * 1e-3, "check": False}
    best = None
    for _ in range(20):  # the fastest of 20, as the run takes about a millisecond
        out = json.loads(subprocess.run([vibro, "simulate", "-"], input=json.dumps(s),
                                        capture_output=True, text=True, check=True).stdout)
        st = out["stats"]
        if best is None or st["wall_ms"] < best[2]:
            best = (st["steps"], st["rhs_evals"], st["wall_ms"])
    return best[0], best[1], best[2] / 1e3


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--vibro", default=os.path.join(ROOT, "build", "vibro"))
    a.add_argument("--rtols", default="1e-6,1e-8,1e-10,1e-12")
    o = a.parse_args()
    scene = json.loads(subprocess.run([o.vibro, "preset", "impact-oscillator"], capture_output=True,
                                      text=True, check=True).stdout)
    Omega = 7.0
    t_end = 70 * 2 * math.pi / Omega
    print("| rtol | SciPy steps | SciPy rhs | SciPy µs/step | vibro steps | vibro rhs | vibro µs/step | per-step ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for rtol in [float(x) for x in o.rtols.split(",")]:
        ss, sf, st = scipy_run(scene, Omega, t_end, rtol)
        vs, vf, vt = vibro_run(o.vibro, scene, Omega, t_end, rtol)
        print("| %g | %d | %d | %.1f | %d | %d | %.2f | %.0f× |" % (
            rtol, ss, sf, 1e6 * st / ss, vs, vf, 1e6 * vt / vs, (st / ss) / (vt / vs)))


if __name__ == "__main__":
    main()
