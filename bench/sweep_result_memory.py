#!/usr/bin/env python3
"""Peak resident memory of `vibro serve` while clients fetch the largest sweep it allows (issue 31,
item 3: a sweep's result must not be built whole on a connection thread).

Usage: python3 bench/sweep_result_memory.py [--vibro build/vibro] [--fetches 4] [--formats json,csv]
Starts `vibro serve` on a free port with its default limits, runs the largest stroboscopic sweep
they allow (the impact oscillator at 1,000 values of F0, 999 periods recorded after 1: 10^6
section points, 10^6 periods), then for each format fetches its result N times at once and prints
the server's resident memory (VmRSS from /proc) before, its peak (VmHWM) during the fetches, the
bytes and the seconds of each fetch.
"""
import argparse
import json
import re
import subprocess
import threading
import time
import urllib.error
import urllib.request


def status(pid, key):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1]) / 1024.0  # MB
    return float("nan")


def reset_peak(pid):
    """Resets VmHWM to VmRSS (Linux 4.0+), so the peak is the fetches' own."""
    with open(f"/proc/{pid}/clear_refs", "w") as f:
        f.write("5")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--vibro", default="build/vibro")
    ap.add_argument("--fetches", type=int, default=4)
    ap.add_argument("--formats", default="json,csv")
    ap.add_argument("--count", type=int, default=1000)
    args = ap.parse_args()
    server = subprocess.Popen([args.vibro, "serve", "--port", "0", "--quiet"],
                              stdout=subprocess.PIPE, text=True)
    try:
        line = server.stdout.readline()
        base = re.search(r"http://[\d.]+:\d+", line).group(0)
        scene = json.loads(subprocess.run([args.vibro, "preset", "impact-oscillator"],
                                          capture_output=True, text=True, check=True).stdout)
        scene["model"]["pellets"][0]["Omega"] = 7.0  # T = 0.9 s: 1000 periods within t_end
        scene["sweep"] = {"parameter": "model.pellets[0].F0", "from": 0.1, "to": 0.6,
                          "count": args.count, "transient": 1, "record": 999,
                          "section": "stroboscopic", "continuation": "none"}
        post = urllib.request.Request(base + "/api/sweep", json.dumps(scene).encode(),
                                      {"Content-Type": "application/json"})
        job = json.load(urllib.request.urlopen(post))
        at = base + "/api/jobs/" + job["id"]
        started = time.monotonic()
        while True:
            s = json.load(urllib.request.urlopen(at))
            if s["status"] not in ("queued", "running"):
                break
            time.sleep(0.5)
        if s["status"] != "done":
            raise SystemExit(f"the sweep ended {s}")
        print(f"sweep: {args.count} runs in {time.monotonic() - started:.1f} s")
        print(f"server after the sweep: VmRSS {status(server.pid, 'VmRSS'):.1f} MB, "
              f"VmHWM {status(server.pid, 'VmHWM'):.1f} MB")
        for fmt in args.formats.split(","):
            reset_peak(server.pid)
            results = []

            def fetch():
                t0 = time.monotonic()
                n = 0
                try:
                    with urllib.request.urlopen(f"{at}/result?format={fmt}") as r:
                        while chunk := r.read(1 << 16):
                            n += len(chunk)
                except urllib.error.HTTPError as e:  # a vector image of too many points: 400
                    results.append((f"{e.code} {json.load(e).get('field')}", time.monotonic() - t0))
                    return
                results.append((n, time.monotonic() - t0))

            threads = [threading.Thread(target=fetch) for _ in range(args.fetches)]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            sizes = ", ".join(f"{n / 1e6:.1f} MB in {s:.1f} s" if isinstance(n, int) else n
                              for n, s in results)
            print(f"{fmt}, {args.fetches} fetches at once: {sizes}; "
                  f"server peak VmHWM {status(server.pid, 'VmHWM'):.1f} MB")
    finally:
        server.terminate()
        server.wait()


if __name__ == "__main__":
    main()
