#!/usr/bin/env python3
"""The front door (issue 14) tested as an attacker would, on loopback: scripts/deploy.sh starts
nginx and two `vibro serve` replicas, and through nginx
- the page and the API answer, and a sweep job's polls reach the replica that holds it;
- a header flood (10^6 lines, 54 MB) is refused early without growing any replica's memory;
- 150 slowloris connections for 15 s leave normal requests answering within 2 s;
- two pipelined requests are both answered; two Content-Length headers are refused with 400;
- a replica killed with SIGKILL under load loses no request, and is restarted;
- a soak (64 connections, mixed requests, SOAK seconds) gives no 5xx and flat memory;
- with no replica listening, the API answers 503 with Retry-After, as a busy replica does;
- SIGTERM stops nginx and every replica, leaving no process behind.

Usage: front_door_test.py path/to/vibro [--soak SECONDS]   (stdlib only; needs nginx)
"""
import argparse
import http.client
import json
import os
import re
import select
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
failures = []


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + (f": {detail}" if detail else ""), flush=True)
    if not ok:
        failures.append(name)


def free_port_block(n):
    """A port P with P … P+n all free on loopback."""
    for base in range(20000 + os.getpid() % 20000, 60000, n + 7):
        socks = []
        try:
            for k in range(n + 1):
                s = socket.socket()
                s.bind(("127.0.0.1", base + k))
                socks.append(s)
            return base
        except OSError:
            continue
        finally:
            for s in socks:
                s.close()
    raise SystemExit("no free ports")


def rss_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


class FrontDoor:
    def __init__(self, vibro, replicas=2, replicas_answer=True):
        self.port = free_port_block(replicas)
        self.replicas = replicas
        self.run = tempfile.mkdtemp(prefix="vibro-front-door-")
        os.chmod(self.run, 0o755)
        self.proc = subprocess.Popen(
            ["bash", os.path.join(ROOT, "scripts", "deploy.sh"), "--port", str(self.port),
             "--replicas", str(replicas), "--run", self.run, "--vibro", vibro, "--",
             "--threads", "1", "--cache-mib", "8"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        self.output = []
        threading.Thread(target=lambda: self.output.extend(self.proc.stdout), daemon=True).start()
        deadline = time.time() + 60
        while time.time() < deadline:
            try:
                if not replicas_answer:
                    if self.get("/")[0] == 200:  # nginx is up
                        return
                elif self.get("/api/health")[0] == 200 and all(
                        self.replica_up(k) for k in range(1, replicas + 1)):
                    return
            except OSError:
                pass
            time.sleep(0.2)
        raise SystemExit("the front door did not come up:\n" + "".join(self.output))

    def replica_pid(self, k):
        with open(os.path.join(self.run, f"replica{k}.pid")) as f:
            return int(f.read())

    def replica_up(self, k):
        try:
            c = http.client.HTTPConnection("127.0.0.1", self.port + k, timeout=2)
            c.request("GET", "/api/health")
            return c.getresponse().status == 200
        except (OSError, ValueError):
            return False

    def connection(self, timeout=10):
        return http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)

    def get(self, path, conn=None):
        c = conn or self.connection()
        c.request("GET", path)
        r = c.getresponse()
        return r.status, r.read(), r

    def post(self, path, body, conn=None):
        c = conn or self.connection()
        c.request("POST", path, body=body, headers={"Content-Type": "application/json"})
        r = c.getresponse()
        return r.status, r.read(), r

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        try:
            self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(self.proc.pid, signal.SIGKILL)
            return False
        return True


def raw(door, data, read_for=3.0):
    """Sends bytes on a fresh connection and returns what comes back within read_for seconds."""
    s = socket.create_connection(("127.0.0.1", door.port), timeout=read_for)
    s.sendall(data)
    got = b""
    end = time.time() + read_for
    try:
        while time.time() < end:
            chunk = s.recv(65536)
            if not chunk:
                break
            got += chunk
    except socket.timeout:
        pass
    s.close()
    return got


def test_page_and_api(door):
    status, body, _ = door.get("/")
    check("the page is served by nginx", status == 200 and b"<html" in body.lower())
    status, body, r = door.get("/api/presets")
    check("the API answers through it", status == 200 and b"impact-oscillator" in body)
    c = door.connection()
    c.request("GET", "/api/presets", headers={"Accept-Encoding": "gzip"})
    r = c.getresponse()
    r.read()
    check("JSON is compressed", r.getheader("Content-Encoding") == "gzip")
    # Round robin let the replicas' queues drift apart under load (p99 184-220 ms against 130 ms
    # at 64 connections, docs/ROBUSTNESS.md): requests go where the fewest are in hand.
    with open(os.path.join(door.run, "nginx.conf")) as f:
        upstream = f.read().split("upstream vibro {", 1)[1].split("}", 1)[0]
    check("the replicas are chosen by least connections", "least_conn;" in upstream)


def test_sweep_jobs(door):
    scene = json.loads(door.get("/api/presets/impact-oscillator")[1])
    scene["sweep"].update(count=8, transient=20, record=10, continuation="none")
    ids = []
    for _ in range(4):  # several jobs: both replicas get some
        status, body, r = door.post("/api/sweep", json.dumps(scene))
        if status != 202:
            check("a sweep job is accepted", False, f"{status} {body[:200]}")
            return
        ids.append(r.getheader("Location"))
    check("job ids name their replica", all(i.startswith("/api/jobs/r") for i in ids), str(ids))
    check("jobs land on both replicas", len({i.split("-")[0] for i in ids}) == 2, str(ids))
    polls_ok = True
    for location in ids:
        for _ in range(200):
            status, body, _ = door.get(location)
            polls_ok = polls_ok and status == 200
            if not polls_ok or json.loads(body)["status"] in ("done", "failed", "cancelled"):
                break
            time.sleep(0.05)
        status, body, _ = door.get(location + "/result?format=csv")
        polls_ok = polls_ok and status == 200 and body.count(b"\n") > 8
    check("every poll and result reaches the job's replica", polls_ok)


def test_header_flood(door):
    pids = [door.replica_pid(k) for k in range(1, door.replicas + 1)]
    before = [rss_mb(p) for p in pids]
    s = socket.create_connection(("127.0.0.1", door.port), timeout=5)
    s.sendall(b"GET /api/health HTTP/1.1\r\nHost: x\r\n")
    line = b"X-Flood: " + b"a" * 43 + b"\r\n"  # 54 bytes
    block = line * 1000
    sent, answered_at, answer = 0, None, b""
    try:
        for _ in range(1000):  # 10^6 lines; nginx drains what follows its answer for a while
            s.sendall(block)
            sent += len(block)
            if answered_at is None and select.select([s], [], [], 0)[0]:
                answered_at = sent
                answer = s.recv(4096)
    except OSError:
        pass
    if not answer:
        try:
            s.settimeout(2)
            answer = s.recv(4096)
        except OSError:
            pass
    s.close()
    after = [rss_mb(p) for p in pids]
    # How much the client pushed before it read the answer depends on socket buffers and load;
    # that nginx refused the head (431, as vibro alone does, after its 33 KiB) does not. Its
    # access log says so (there as 400, the status nginx logs a head too large with) even when a
    # reset lost the answer.
    with open(os.path.join(door.run, "access.log")) as log:
        logged = any(re.search(r'"GET /api/health HTTP/1.1" (400|431) ', line) for line in log)
    refused = answer.startswith(b"HTTP/1.1 431") or logged
    check("a header flood is refused with 431", refused,
          f"answered {answer[:24]!r} after {answered_at} bytes of 54 MB, logged {logged}")
    grew = max(a - b for a, b in zip(after, before))
    check("no replica grows under the flood", grew < 5, f"{grew:+.1f} MB")
    check("the service answers after it", door.get("/api/health")[0] == 200)


def test_slowloris(door, connections=150, seconds=15):
    stop = time.time() + seconds
    socks = []

    def open_slow():
        s = socket.create_connection(("127.0.0.1", door.port), timeout=5)
        s.sendall(b"GET /api/health HTTP/1.1\r\nHost: x\r\n")
        return s

    for _ in range(connections):
        socks.append(open_slow())
    worst, answered, asked = 0.0, 0, 0
    last_drip = time.time()
    while time.time() < stop:
        t0 = time.time()
        asked += 1
        try:
            if door.get("/api/presets", door.connection(timeout=5))[0] == 200:
                answered += 1
        except OSError:
            pass
        worst = max(worst, time.time() - t0)
        if time.time() - last_drip > 4.5:  # a header line every 4.5 s, reopening what was closed
            last_drip = time.time()
            for i, s in enumerate(socks):
                try:
                    s.sendall(b"X-Slow: 1\r\n")
                except OSError:
                    s.close()
                    socks[i] = open_slow()
        time.sleep(0.1)
    for s in socks:
        s.close()
    check(f"{connections} slowloris connections for {seconds} s: normal requests answer",
          answered == asked and worst < 2.0, f"{answered}/{asked}, slowest {worst:.2f} s")


def test_pipelining_and_smuggling(door):
    got = raw(door, b"GET /api/health HTTP/1.1\r\nHost: x\r\n\r\n"
                    b"GET /api/limits HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
    check("two pipelined requests are both answered", got.count(b"HTTP/1.1 200") == 2,
          f"{got.count(b'HTTP/1.1 ')} answers")
    body = b'{"model": {"R": 1}}'
    got = raw(door, b"POST /api/simulate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                    b"Content-Length: " + str(len(body)).encode() + b"\r\nContent-Length: 5\r\n"
                    b"Connection: close\r\n\r\n" + body)
    check("two Content-Length headers are refused with 400", got.startswith(b"HTTP/1.1 400"),
          repr(got[:40]))


def test_errors_are_json(door):
    """What nginx refuses itself comes back as the API's JSON, as a replica's refusals do."""
    cases = {
        400: b"NONSENSE\r\n\r\n",
        413: b"POST /api/simulate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
             b"Content-Length: 99999999\r\nConnection: close\r\n\r\n{",
        414: b"GET /api/render?preset=" + b"p" * 9000 + b" HTTP/1.1\r\nHost: x\r\n\r\n",
        431: b"GET /api/health HTTP/1.1\r\nHost: x\r\nX-Big: " + b"a" * 9000 + b"\r\n\r\n",
        501: b"POST /api/simulate HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: gzip\r\n"
             b"Connection: close\r\n\r\n",
        505: b"GET /api/health HTTP/2.7\r\nHost: x\r\n\r\n",
    }
    for status, request in cases.items():
        got = raw(door, request)
        head, _, body = got.partition(b"\r\n\r\n")
        try:
            fields = json.loads(body)
        except ValueError:
            fields = {}
        check(f"nginx's {status} is JSON naming a field",
              head.startswith(b"HTTP/1.1 %d" % status) and b"application/json" in head
              and "error" in fields and "field" in fields, repr(got[:160]))


def load(door, seconds, threads, make_request, results):
    """Requests from `threads` keep-alive clients for `seconds`; appends statuses to results."""
    def client(k):
        conn = door.connection(timeout=30)
        n = 0
        end = time.time() + seconds
        while time.time() < end:
            method, path, body = make_request(k, n)
            n += 1
            try:
                conn.request(method, path, body=body,
                             headers={"Content-Type": "application/json"} if body else {})
                r = conn.getresponse()
                r.read()
                results.append(r.status)
            except (OSError, http.client.HTTPException) as e:
                results.append(repr(e))
                conn.close()
                conn = door.connection(timeout=30)
    workers = [threading.Thread(target=client, args=(k,)) for k in range(threads)]
    for w in workers:
        w.start()
    return workers


def mixed(k, n):
    """A mix of what users ask: the page, presets, uncached renders and runs, a simulation."""
    kind = (k + n) % 5
    if kind == 0:
        return "GET", "/", None
    if kind == 1:
        return "GET", "/api/presets", None
    t_end = 0.5 + ((k * 7919 + n * 104729) % 5000) / 1000.0  # mostly uncached
    if kind == 2:
        return "GET", f"/api/render?preset=paper&t_end={t_end:.3f}&width=600&height=400", None
    if kind == 3:
        return "GET", f"/api/simulate?preset=paper&t_end={t_end:.3f}", None
    return "POST", "/api/simulate", json.dumps({"model": {"R": 0.5, "pellets": [
        {"m": 0.1, "phi0": 0.3 + 1e-4 * n, "dphi0": 0.0}], "limiters": [{"angle": 0.0, "k": 0.7}]},
        "t_end": 2.0})


def test_replica_killed(door):
    results = []
    workers = load(door, 6, 8, mixed, results)
    time.sleep(2)
    victim = door.replica_pid(1)
    os.kill(victim, signal.SIGKILL)
    for w in workers:
        w.join()
    bad = [r for r in results if r != 200]
    check("a replica killed with SIGKILL under load loses no request", not bad and len(results) > 50,
          f"{len(results)} requests, not answered 200: {bad[:5]}")
    restarted = False
    for _ in range(50):
        try:
            restarted = door.replica_pid(1) != victim and door.replica_up(1)
        except (OSError, ValueError):
            pass
        if restarted:
            break
        time.sleep(0.2)
    check("the killed replica is restarted", restarted)


def test_soak(door, seconds):
    pids = [door.replica_pid(k) for k in range(1, door.replicas + 1)]
    results = []
    workers = load(door, seconds, 64, mixed, results)
    time.sleep(min(10, seconds / 3))
    warm = [rss_mb(p) for p in pids]
    for w in workers:
        w.join()
    end = [rss_mb(p) for p in pids]
    errors = [r for r in results if not isinstance(r, int) or r >= 500]
    check(f"soak: 64 connections, mixed, {seconds} s, no 5xx", not errors and len(results) > 100,
          f"{len(results)} requests, {len(errors)} failed: {errors[:3]}")
    grew = max(e - w for e, w in zip(end, warm))
    check("soak: the replicas' memory is flat", grew < 20,
          f"{', '.join(f'{w:.0f}→{e:.0f} MB' for w, e in zip(warm, end))}")


def test_no_replica(vibro):
    """Replicas that never listen (a stand-in for `vibro` that only sleeps): nginx finds no
    replica to answer, and says so as a busy replica does, 503 with Retry-After and the API's
    JSON, instead of its 502."""
    stand_in = os.path.join(tempfile.mkdtemp(prefix="vibro-stand-in-"), "vibro")
    with open(stand_in, "w") as f:
        f.write("#!/bin/sh\nexec sleep 600\n")
    os.chmod(stand_in, 0o755)
    door = FrontDoor(stand_in, replicas_answer=False)
    try:
        for method, path, body in [("GET", "/api/health", None),
                                   ("POST", "/api/simulate", json.dumps({"preset": "paper"}))]:
            status, got, r = (door.get(path) if method == "GET" else door.post(path, body))
            try:
                fields = json.loads(got)
            except ValueError:
                fields = {}
            check(f"no replica: {method} {path} is 503 with Retry-After, naming the server",
                  status == 503 and r.getheader("Retry-After") == "1"
                  and fields.get("field") == "server", f"{status} {r.getheaders()} {got[:120]!r}")
    finally:
        door.stop()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vibro")
    ap.add_argument("--soak", type=float, default=60)
    args = ap.parse_args()
    door = FrontDoor(os.path.abspath(args.vibro))
    try:
        test_page_and_api(door)
        test_sweep_jobs(door)
        test_header_flood(door)
        test_pipelining_and_smuggling(door)
        test_errors_are_json(door)
        test_slowloris(door)
        test_replica_killed(door)
        test_soak(door, args.soak)
        test_no_replica(os.path.abspath(args.vibro))
    finally:
        pids = []
        for k in range(1, door.replicas + 1):
            try:
                pids.append(door.replica_pid(k))
            except (OSError, ValueError):
                pass
        with open(os.path.join(door.run, "nginx.pid")) as f:
            pids.append(int(f.read()))
        stopped = door.stop()
        time.sleep(0.5)
        alive = [p for p in pids if os.path.exists(f"/proc/{p}")]
        left = subprocess.run(["pgrep", "-f", door.run], capture_output=True, text=True).stdout.split()
        check("SIGTERM stops nginx and every replica", stopped and not alive and not left,
              f"alive {alive}, left {left}")
    print(f"{len(failures)} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
