"""vibro.sweep: the points of `vibro sweep`, bit for bit, in parallel with the GIL released; its
progress, and Ctrl-C."""

import csv
import io
import json
import math
import textwrap
import threading
import time

import numpy as np
import pytest

import vibro
from conftest import HANG, interrupt, run_cli
from test_render import same_figure


def small_sweep(count=24, continuation="both", **extra):
    scene = vibro.preset("impact-oscillator")
    scene["sweep"].update(count=count, transient=40, record=16, continuation=continuation, **extra)
    return scene


def as_csv_number(text):
    return math.nan if text == "" else float(text)


def test_points_are_the_columns_of_the_csv(scene_file, tmp_path):
    scene = small_sweep(lyapunov=True)
    result = vibro.sweep(scene, threads=2)
    run_cli("sweep", scene_file(scene), "--threads", "2", "-o", tmp_path / "s.csv")
    rows = list(csv.DictReader(io.StringIO((tmp_path / "s.csv").read_text())))
    points = result.points
    assert list(points)[:-1] == list(rows[0])  # the CSV's columns in its order, then "run"
    assert len(rows) == len(points["t"]) == result.stats["points"] > 100
    for name in rows[0]:
        column = points[name]
        if name == "trusted":
            expected = np.array([r[name] == "1" for r in rows])
        elif column.dtype == np.int64:
            expected = np.array([int(r[name]) for r in rows])
        else:
            expected = np.array([as_csv_number(r[name]) for r in rows])
        assert np.array_equal(column, expected, equal_nan=True), name
    assert result.to_csv() == (tmp_path / "s.csv").read_text()


def test_to_json_is_the_command_lines_output(scene_file):
    scene = small_sweep()
    result = vibro.sweep(scene, threads=2)
    _, out, _ = run_cli("sweep", scene_file(scene), "--threads", "2")
    ours, theirs = json.loads(result.to_json()), json.loads(out)
    for j in (ours, theirs):
        j["stats"]["wall_ms"] = 0
    assert ours == theirs
    runs = result.runs
    assert np.array_equal(runs["period"], theirs["runs"]["period"])
    assert list(runs["termination"]) == theirs["runs"]["termination"]
    assert result.parameter == "model.pellets[0].Omega" and result.parameter2 is None


def test_the_same_points_on_any_number_of_threads():
    scene = small_sweep()
    one, three = vibro.sweep(scene, threads=1), vibro.sweep(scene, threads=3)
    assert one.stats["threads"] == 1 and three.stats["threads"] == 3
    for name, column in one.points.items():
        assert np.array_equal(column, three.points[name], equal_nan=True), name


def test_progress_counts_the_runs_on_the_calling_thread():
    calls = []
    caller = threading.get_ident()
    result = vibro.sweep(small_sweep(), threads=2,
                         progress=lambda done, total: calls.append((done, total, threading.get_ident())))
    runs = result.stats["runs"]
    assert calls and calls[-1][:2] == (runs, runs)
    assert [c[0] for c in calls] == sorted({c[0] for c in calls})  # growing, no repeats
    assert {c[2] for c in calls} == {caller}


def test_an_exception_in_progress_stops_the_sweep():
    def stop(done, total):
        if done > 0:
            raise RuntimeError("enough")

    start = time.monotonic()
    with pytest.raises(RuntimeError, match="enough"):
        vibro.sweep(small_sweep(count=400), threads=2, progress=stop)
    assert time.monotonic() - start < HANG


def test_other_python_threads_run_meanwhile():
    done = threading.Event()
    worker = threading.Thread(target=lambda: (vibro.sweep(small_sweep(count=60), threads=1), done.set()))
    ticks = 0
    worker.start()
    while not done.is_set() and worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    assert ticks > 20  # with the GIL held through the sweep this thread could not tick at all


def test_a_2d_sweep_and_its_regime_map():
    scene = small_sweep(count=6, continuation="none")
    scene["sweep"]["parameter2"] = {"parameter": "model.pellets[0].F0", "from": 0.2, "to": 0.4, "count": 3}
    result = vibro.sweep(scene)
    assert result.parameter2 == "model.pellets[0].F0"
    assert len(result.runs["value"]) == 18
    assert result.render().startswith(b"\x89PNG")
    assert result._repr_png_().startswith(b"\x89PNG")


def test_render_draws_as_the_command_line(scene_file, tmp_path):
    scene = small_sweep()
    result = vibro.sweep(scene, threads=2)
    for plot, name in (("", "bif.png"), ("section", "sec.svg")):
        run_cli("sweep", scene_file(scene), "--threads", "2", "--plot", plot or "bifurcation", "-o", tmp_path / name)
        image = result.render(plot=plot, format=name[-3:])
        assert same_figure(image, (tmp_path / name).read_bytes()), name
    with pytest.raises(vibro.SceneError) as e:
        result.render(plot="lyapunov")
    assert e.value.field == "sweep.lyapunov"


CTRL_C = textwrap.dedent(
    """
    import sys, time
    sys.path.insert(0, sys.argv[1])
    import vibro
    scene = vibro.preset("impact-oscillator")
    scene["sweep"].update(count=4000, transient=400)
    started = None
    def progress(done, total):
        global started
        if started is None:
            started = time.monotonic()
            print("started", total, flush=True)
    try:
        vibro.sweep(scene, threads=2, progress=progress)
        print("finished")
    except KeyboardInterrupt:
        print("interrupted after %.3f s" % (time.monotonic() - started), flush=True)
    """
)


def test_ctrl_c_cancels_cleanly():
    out, returncode = interrupt(CTRL_C, after=0.3)
    assert out.startswith("interrupted"), out
    assert returncode == 0


def test_basins_give_each_run_its_attractor(scene_file, tmp_path):
    scene = vibro.preset("impact-oscillator")
    scene["model"]["pellets"][0]["Omega"] = 6.8
    scene["sweep"] = {"parameter": "model.pellets[0].phi0", "from": 0.05, "to": 1.5, "count": 5,
                      "parameter2": {"parameter": "model.pellets[0].dphi0", "from": -7.0, "to": 7.0, "count": 5},
                      "transient": 40, "record": 4, "classify": "attractor"}
    result = vibro.sweep(scene, threads=2)
    run_cli("sweep", scene_file(scene), "--threads", "2", "-o", tmp_path / "b.json")
    expected = json.loads((tmp_path / "b.json").read_text())
    assert result.attractors == expected["attractors"]
    assert list(result.points["attractor"]) == expected["points"]["attractor"]
    assert list(result.runs["attractor"]) == expected["runs"]["attractor"]
    assert result.render().startswith(b"\x89PNG")  # the basins plot, the default here
    assert vibro.sweep(small_sweep(count=3)).attractors is None
    scene["sweep"]["parameter"] = "model.pellets[0].F0"
    with pytest.raises(vibro.SceneError) as e:
        vibro.sweep(scene)
    assert e.value.field == "sweep.parameter"
