#!/usr/bin/env python3
"""The impact-oscillator sweep the way a researcher scripts it today: SciPy's solve_ivp (DOP853)
with a terminal event at the stop, restarted after every impact, per value of Omega.

Usage: /usr/bin/python3 bench/peers/sweep_scipy.py [--values N] [--rtols 1e-6,1e-8,...] [--vibro build/vibro]
                                                   [--method dop853|taylor|auto|...]
Runs N values of the preset's 1,000-value sweep (every 1000/N-th), 50 transient and 20 recorded
periods each, with SciPy and with vibro (--method, DOP853 unless told, one thread, the check off)
at each tolerance, vibro both as one sweep per value and as one sweep of the N values, and
prints per tolerance the seconds per run of both and the median error of their stroboscopic
points against a truth computed by SciPy at rtol 1e-13; then the ratio at the same tolerance and
at matched error (SciPy's seconds at vibro's error, interpolated log-log on SciPy's curve).
The model: phi'' = F0 cos(Omega t)/(m R) - (g/R) sin phi, a stop at phi = 0 (restitution k) that
the pellet strikes from phi > 0; a strike slower than 1e-9 rad/s leaves it resting against the
stop until the force pulls it away (the script's own stand-in for a summed chatter series).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def load_preset(vibro):
    return json.loads(subprocess.run([vibro, "preset", "impact-oscillator"], capture_output=True,
                                     text=True, check=True).stdout)


def impact_oscillator(scene, Omega):
    """The preset's right-hand side at Omega, its strike at the stop (a terminal event) and the
    stop's restitution."""
    m, R, g = scene["model"]["pellets"][0]["m"], scene["model"]["R"], 9.81
    F0, psi = scene["model"]["pellets"][0]["F0"], scene["model"]["pellets"][0].get("psi", 0.0)
    w2 = g / R

    def rhs(t, y):
        return [y[1], F0 * math.cos(Omega * t + psi) / (m * R) - w2 * math.sin(y[0])]

    def strike(t, y):
        return y[0]
    strike.terminal = True
    strike.direction = -1
    return rhs, strike, scene["model"]["limiters"][0]["k"]


def section(scene, Omega, transient, record, rtol):
    psi = scene["model"]["pellets"][0].get("psi", 0.0)
    rhs, strike, k = impact_oscillator(scene, Omega)
    T = 2 * math.pi / Omega
    times = [n * T for n in range(transient, transient + record + 1)]
    t_end = times[-1]

    t, y = 0.0, [scene["model"]["pellets"][0]["phi0"], scene["model"]["pellets"][0]["dphi0"]]
    points = []
    while t < t_end:
        wanted = [s for s in times if s > t and s <= t_end]
        sol = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=rtol, atol=rtol * 1e-3,
                        events=strike, dense_output=True)
        stop = sol.t_events[0][0] if sol.status == 1 else t_end
        points += [(s, *sol.sol(s)) for s in wanted if s <= stop]
        if sol.status != 1:
            break
        t, v = stop, -k * sol.y_events[0][0][1]
        if abs(v) > 1e-9:
            y = [0.0, v]
            continue
        # At rest against the stop until the force pulls it off: cos(Omega t + psi) > 0.
        phase = (Omega * t + psi) % (2 * math.pi)
        wait = 0.0 if (phase < math.pi / 2 or phase > 3 * math.pi / 2) else (3 * math.pi / 2 - phase) / Omega
        for s in times:
            if t < s <= t + wait:
                points.append((s, 0.0, 0.0))
        t, y = t + wait, [0.0, 0.0]
    return points


def vibro_sweep(vibro, scene, values, transient, record, rtol, method):
    """One vibro sweep over evenly spaced values (values[0] … values[-1]), one thread, the check
    off: its output."""
    s = dict(scene)
    s["solver"] = {"method": method, "rtol": rtol, "atol": rtol * 1e-3, "check": False}
    s["sweep"] = dict(scene["sweep"], **{"from": values[0], "to": values[-1], "count": len(values),
                                         "transient": transient, "record": record,
                                         "continuation": "none"})
    return json.loads(subprocess.run([vibro, "sweep", "-", "--threads", "1"], input=json.dumps(s),
                                     capture_output=True, text=True, check=True).stdout)


def vibro_sections(vibro, scene, omegas, transient, record, rtol, method):
    """vibro on the same values: one sweep per value. Returns (seconds per run,
    {Omega: [(phi, dphi)]})."""
    seconds, points = 0.0, {}
    for Om in omegas:
        out = vibro_sweep(vibro, scene, [Om], transient, record, rtol, method)
        seconds += out["stats"]["wall_ms"] / 1e3
        points[Om] = list(zip(out["points"]["phi"], out["points"]["dphi"]))
    return seconds / len(omegas), points


def vibro_one_sweep(vibro, scene, omegas, transient, record, rtol, method):
    """vibro on the same values as one sweep (they are evenly spaced), as vibro is used: a fresh
    process's first run is cold (a one-value sweep takes 0.9 ms, a run inside a long sweep 0.4,
    for the same instructions), and here only one run in ten pays that. Returns (seconds per run,
    {Omega: [(phi, dphi)]})."""
    out = vibro_sweep(vibro, scene, omegas, transient, record, rtol, method)
    runs = sorted(set(out["points"]["run"]))
    points = {Om: [] for Om in omegas}
    for run, phi, dphi in zip(out["points"]["run"], out["points"]["phi"], out["points"]["dphi"]):
        points[omegas[runs.index(run)]].append((phi, dphi))
    return out["stats"]["wall_ms"] / 1e3 / len(omegas), points


def error(points, truth, speed):
    """The median distance of the section points from the truth's (φ̇ scaled by sqrt(R/g))."""
    far = [max(abs(a[0] - b[0]), abs(a[1] - b[1]) / speed)
           for Om in truth for a, b in zip(points[Om], truth[Om])]
    return float(np.median(far))


def seconds_at(error_wanted, curve):
    """The seconds per run of a (error, seconds) curve at an error, interpolated log-log; None
    outside the curve's range."""
    curve = sorted(curve)
    for (e0, s0), (e1, s1) in zip(curve, curve[1:]):
        if e0 <= error_wanted <= e1 and e0 > 0:
            w = math.log(error_wanted / e0) / math.log(e1 / e0) if e1 > e0 else 0.0
            return math.exp(math.log(s0) + w * math.log(s1 / s0))
    return None


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--values", type=int, default=20)
    a.add_argument("--rtols", default="1e-6,1e-8,1e-10,1e-12")
    a.add_argument("--vibro", default=os.path.join(ROOT, "build", "vibro"))
    a.add_argument("--method", default="dop853")
    o = a.parse_args()
    scene = load_preset(o.vibro)
    sweep = scene["sweep"]
    omegas = [sweep["from"] + (sweep["to"] - sweep["from"]) * i / 999 for i in range(0, 1000, 1000 // o.values)]
    transient, record = 50, 20
    speed = math.sqrt(9.81 / scene["model"]["R"])

    # The truth: SciPy at 1e-13, independent of vibro.
    truth = {Om: [(p[1], p[2]) for p in section(scene, Om, transient, record, 1e-13)] for Om in omegas}
    rows = []
    for rtol in [float(x) for x in o.rtols.split(",")]:
        started = time.perf_counter()
        peer = {Om: [(p[1], p[2]) for p in section(scene, Om, transient, record, rtol)] for Om in omegas}
        scipy_s = (time.perf_counter() - started) / len(omegas)
        vibro_s, ours = vibro_sections(o.vibro, scene, omegas, transient, record, rtol,
                                         o.method)
        one_s, together = vibro_one_sweep(o.vibro, scene, omegas, transient, record, rtol,
                                          o.method)
        rows.append({"rtol": rtol, "scipy_s_per_run": scipy_s, "scipy_error": error(peer, truth, speed),
                     "vibro_s_per_run": vibro_s, "vibro_error": error(ours, truth, speed),
                     "ratio_same_rtol": scipy_s / vibro_s,
                     "vibro_one_sweep_s_per_run": one_s,
                     "vibro_one_sweep_error": error(together, truth, speed),
                     "ratio_same_rtol_one_sweep": scipy_s / one_s})
    scipy_curve = [(r["scipy_error"], r["scipy_s_per_run"]) for r in rows]
    for r in rows:
        s = seconds_at(r["vibro_error"], scipy_curve)
        r["ratio_matched_error"] = s / r["vibro_s_per_run"] if s else None
        s = seconds_at(r["vibro_one_sweep_error"], scipy_curve)
        r["ratio_matched_error_one_sweep"] = s / r["vibro_one_sweep_s_per_run"] if s else None
    print(json.dumps({"values": len(omegas), "method": o.method, "periods_per_run": transient + record,
                      "truth": "SciPy DOP853 at rtol 1e-13", "rows": rows}, indent=1))


if __name__ == "__main__":
    main()
