"""Shared by the Python module's tests: the module built in build/python (not an installed one),
and the command line of the same build, whose answers the module's must equal."""

import json
import os
import pathlib
import re
import signal
import subprocess
import sys
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("VIBRO_BUILD", ROOT / "build"))
# ctest sets PYTHONPATH; a bare `pytest python/tests` finds the build's package here.
sys.path.insert(0, str(BUILD / "python"))

import vibro  # noqa: E402

# Tests that wait for work to end bound it generously: a hang fails instead of stalling CI.
HANG = 300


def interrupt(code, after):
    """Runs `code` in a child Python (argv[1]: the package's folder) and sends it SIGINT `after`
    seconds past the first line it prints: its output and exit code."""
    child = subprocess.Popen(
        [sys.executable, "-c", code, str(BUILD / "python")], stdout=subprocess.PIPE, text=True
    )
    try:
        assert child.stdout.readline().startswith("started")
        time.sleep(after)
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=HANG)
    finally:
        child.kill()
    return out, child.returncode


def pytest_report_header(config):
    return f"vibro from {vibro.__file__}, the command line {BUILD / 'vibro'}"


def run_cli(*args, stdin=None, check=True):
    """`vibro ARGS...` of the same build: (exit code, stdout, stderr)."""
    done = subprocess.run(
        [str(BUILD / "vibro"), *map(str, args)],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=HANG,
    )
    if check and done.returncode not in (0, 1):
        raise AssertionError(f"vibro {' '.join(map(str, args))}: {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def without_wall_clock(text):
    """JSON text with every wall-clock figure (wall_ms, check_wall_ms) set to 0: the one part of
    an answer that changes from run to run."""
    return re.sub(r'("(?:check_)?wall_ms": ?)[-0-9.e+]+', r"\g<1>0", text)


def cli_error(*args, stdin=None):
    """The {"error", "field"} the command line prints for a refused scene."""
    code, _, err = run_cli(*args, stdin=stdin, check=False)
    assert code == 2, err
    return json.loads(err.strip().splitlines()[-1])


@pytest.fixture
def scene_file(tmp_path):
    """Writes a scene dict as a JSON file for the command line; returns its path."""

    def write(scene, name="scene.json"):
        path = tmp_path / name
        path.write_text(json.dumps(scene))
        return path

    return write


def module_is_built_one():
    return pathlib.Path(vibro.__file__).resolve().parent == (BUILD / "python" / "vibro").resolve()
