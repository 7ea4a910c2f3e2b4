#!/usr/bin/env python3
"""The docs' command lines run as written.

Every ```sh or ```bash block of README.md and docs/*.md that the line before it marks
`<!-- runnable -->` is run with bash (`set -eo pipefail`) in a fresh temporary directory that
holds `build` (the built programs, also on PATH as `vibro`) and `docs/scenes`, each block within
a time bound. A block marked `<!-- runnable: server -->` runs with `vibro serve` listening, its
`8080` replaced by the port the server took. A block fails on a non-zero exit or the bound.

Usage: doc_commands_test.py path/to/vibro
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BLOCK = re.compile(r"^<!-- runnable(: server)? -->\n```(?:sh|bash)\n(.*?)^```", re.M | re.S)
SECONDS = 900  # a hang detector: a loaded 2-core machine took over 300 s for README.md's command block


def blocks():
    pages = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
    for page in pages:
        text = open(page, encoding="utf-8").read()
        for m in BLOCK.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            yield os.path.relpath(page, ROOT), line, bool(m.group(1)), m.group(2)


def workdir(vibro):
    work = tempfile.mkdtemp(prefix="doc-commands-")
    os.symlink(os.path.dirname(os.path.abspath(vibro)), os.path.join(work, "build"))
    os.makedirs(os.path.join(work, "docs"))
    os.symlink(os.path.join(ROOT, "docs", "scenes"), os.path.join(work, "docs", "scenes"))
    return work


def start_server(vibro, work):
    log = open(os.path.join(work, "serve.out"), "w+")
    server = subprocess.Popen([vibro, "serve", "--port", "0", "--quiet"], stdout=log,
                              stderr=subprocess.STDOUT, cwd=work)
    for _ in range(300):
        log.seek(0)
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", log.read())
        if m:
            return server, m.group(1)
        time.sleep(0.1)
    server.kill()
    raise RuntimeError("vibro serve did not say its port")


def run(vibro, commands, server):
    work = workdir(vibro)
    process = None
    try:
        if server:
            process, port = start_server(vibro, work)
            commands = commands.replace("8080", port)
        env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(vibro)) + ":" + os.environ["PATH"])
        try:
            done = subprocess.run(["bash", "-c", "set -eo pipefail\n" + commands], cwd=work, env=env,
                                  capture_output=True, text=True, timeout=SECONDS)
        except subprocess.TimeoutExpired:
            return f"did not finish within {SECONDS} s"
        return None if done.returncode == 0 else f"exit {done.returncode}:\n{done.stderr[-2000:]}"
    finally:
        if process:
            process.terminate()
            process.wait(timeout=30)
        shutil.rmtree(work, ignore_errors=True)


def main():
    vibro = sys.argv[1]
    failures = count = 0
    for page, line, server, commands in blocks():
        count += 1
        problem = run(vibro, commands, server)
        name = f"{page}:{line}" + (" (with the server)" if server else "")
        if problem:
            print(f"FAIL {name}: {problem}")
            failures += 1
        else:
            print(f"PASS {name}")
    if count == 0:
        print("FAIL no block is marked <!-- runnable -->")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
