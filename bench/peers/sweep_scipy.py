#!/usr/bin/env python3
"""The impact-oscillator sweep the way a researcher scripts it today: SciPy's solve_ivp (DOP853)
with a terminal event at the stop, restarted after every impact, per value of Omega.

Usage: /usr/bin/python3 bench/peers/sweep_scipy.py [--values N] [--rtol X] [--vibro build/vibro]
Runs N values of the preset's 1,000-value sweep (every 1000/N-th), 50 transient and 20 recorded
periods each, times them, runs vibro on the same values at the same tolerance on one thread, and
prints seconds per run for both, their ratio, and how far their stroboscopic points lie apart.
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


def section(scene, Omega, transient, record, rtol):
    m, R, g = scene["model"]["pellets"][0]["m"], scene["model"]["R"], 9.81
    F0, psi = scene["model"]["pellets"][0]["F0"], scene["model"]["pellets"][0].get("psi", 0.0)
    k = scene["model"]["limiters"][0]["k"]
    w2 = g / R
    T = 2 * math.pi / Omega
    times = [n * T for n in range(transient, transient + record + 1)]
    t_end = times[-1]

    def rhs(t, y):
        return [y[1], F0 * math.cos(Omega * t + psi) / (m * R) - w2 * math.sin(y[0])]

    def strike(t, y):
        return y[0]
    strike.terminal = True
    strike.direction = -1

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


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--values", type=int, default=20)
    a.add_argument("--rtol", type=float, default=1e-8)
    a.add_argument("--vibro", default=os.path.join(ROOT, "build", "vibro"))
    o = a.parse_args()
    scene = load_preset(o.vibro)
    sweep = scene["sweep"]
    omegas = [sweep["from"] + (sweep["to"] - sweep["from"]) * i / 999 for i in range(0, 1000, 1000 // o.values)]
    transient, record = 50, 20

    started = time.perf_counter()
    peer = {Om: section(scene, Om, transient, record, o.rtol) for Om in omegas}
    scipy_s = (time.perf_counter() - started) / len(omegas)

    # vibro on the same values: one sweep per value on one thread, the check off, as above.
    vibro_s, far = 0.0, []
    for Om in omegas:
        s = dict(scene)
        s["solver"] = {"method": "dop853", "rtol": o.rtol, "atol": o.rtol * 1e-3, "check": False}
        s["sweep"] = dict(sweep, **{"from": Om, "to": Om, "count": 1, "transient": transient,
                                    "record": record, "continuation": "none"})
        out = json.loads(subprocess.run([o.vibro, "sweep", "-", "--threads", "1"], input=json.dumps(s),
                                        capture_output=True, text=True, check=True).stdout)
        vibro_s += out["stats"]["wall_ms"] / 1e3
        pts = out["points"]
        for (t, phi, dphi), vphi, vdphi in zip(peer[Om], pts["phi"], pts["dphi"]):
            far.append(max(abs(phi - vphi), abs(dphi - vdphi) / math.sqrt(9.81 / scene["model"]["R"])))
    vibro_s /= len(omegas)
    print(json.dumps({"values": len(omegas), "rtol": o.rtol, "periods_per_run": transient + record,
                      "scipy_s_per_run": scipy_s, "vibro_s_per_run": vibro_s,
                      "ratio": scipy_s / vibro_s,
                      "points_apart_median": float(np.median(far)), "points_apart_max": float(np.max(far))}, indent=1))


if __name__ == "__main__":
    main()
