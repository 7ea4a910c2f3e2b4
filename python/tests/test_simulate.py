"""vibro.simulate: the run of `vibro simulate`, bit for bit, as Python values and numpy arrays."""

import concurrent.futures
import csv
import io
import json
import math
import textwrap
import threading

import numpy as np
import pytest

import vibro
from conftest import interrupt, run_cli, without_wall_clock

PRESETS = [p["name"] for p in vibro.presets()]


@pytest.mark.parametrize("name", PRESETS)
def test_to_json_is_the_command_lines_output(name):
    run = vibro.simulate(vibro.preset(name))
    _, out, _ = run_cli("simulate", "--preset", name)
    assert without_wall_clock(run.to_json()) == without_wall_clock(out)
    assert_parts_are_the_jsons(run)


def assert_parts_are_the_jsons(run):
    """The parts read as Python values are those of the run's JSON: the same values of the same
    types, the keys in the same order (json.dumps writes both alike only then)."""
    whole = json.loads(run.to_json())
    for part in ("summary", "stats", "warnings", "lyapunov"):
        ours = getattr(run, part)
        assert ours == whole.get(part), part
        assert json.dumps(ours) == json.dumps(whole.get(part)), part


def test_a_scene_of_awkward_doubles_reads_as_the_command_line_reads_its_file(scene_file):
    # Doubles whose shortest text has 17 digits, and ones that are not, read back bit for bit.
    scene = vibro.preset("paper")
    scene["t_end"] = 3.0000000000000004
    scene["model"]["pellets"][0]["dphi0"] = 0.1 + 0.2
    scene["model"]["pellets"][1]["phi0"] = 1 / 3
    scene["model"]["mu_s"] = 0.30000000000000004
    run = vibro.simulate(scene, trajectories=True)
    _, out, _ = run_cli("simulate", scene_file(scene), "--trajectories")
    assert without_wall_clock(run.to_json()) == without_wall_clock(out)


def test_events_are_the_columns_of_the_csv(tmp_path):
    run = vibro.simulate(vibro.preset("paper"))
    run_cli("simulate", "--preset", "paper", "-o", tmp_path / "run.csv")
    rows = list(csv.DictReader(io.StringIO((tmp_path / "run.csv").read_text())))
    events = run.events
    assert list(events) == list(rows[0])  # the CSV's columns in its order
    assert {len(a) for a in events.values()} == {len(rows)} and len(rows) > 20
    assert events["t"].dtype == np.float64 and events["limiter"].dtype == np.int64
    assert events["pellet"].dtype == np.int64 and events["dphi_before"].dtype == np.float64
    assert events["kind"].dtype == np.dtype(f"<U{max(len(row['kind']) for row in rows)}")
    for k, row in enumerate(rows):
        assert events["event"][k] == int(row["event"])
        assert events["t"][k] == float(row["t"])  # 17 digits: the same double
        assert events["kind"][k] == row["kind"]
        assert events["pellet"][k] == int(row["pellet"])
        assert events["limiter"][k] == int(row["limiter"])
        assert events["phi"][k] == float(row["phi"])
        assert events["dphi_before"][k] == float(row["dphi_before"])
        assert events["dphi_after"][k] == float(row["dphi_after"])
    collisions = events["kind"] == "collision"
    assert collisions.any()  # the paper scene's collisions: two rows each, one per pellet
    assert np.all(np.unique(events["event"][collisions], return_counts=True)[1] == 2)


def test_a_run_without_events_has_empty_columns():
    scene = vibro.preset("paper")
    scene["t_end"] = 1e-3
    events = vibro.simulate(scene).events
    assert {len(a) for a in events.values()} == {0}
    assert events["kind"].dtype == np.dtype("<U1") and events["t"].dtype == np.float64


def test_trajectories_are_the_samples_of_the_csv(tmp_path):
    run = vibro.simulate(vibro.preset("paper"), trajectories=True)
    run_cli("simulate", "--preset", "paper", "-o", tmp_path / "t.csv", "--what", "trajectory")
    rows = list(csv.reader(io.StringIO((tmp_path / "t.csv").read_text())))[1:]
    flat = []
    for track in run.trajectories:
        for branch in track["branches"]:
            assert len(branch["t"]) == len(branch["phi"]) == len(branch["dphi"])
            for t, phi, dphi in zip(branch["t"], branch["phi"], branch["dphi"]):
                flat.append([t, track["pellet"], branch["index"], phi, dphi])
    assert len(flat) == len(rows) > 1000
    for ours, row in zip(flat, rows):
        assert ours == [float(row[0]), int(row[1]), int(row[2]), float(row[3]), float(row[4])]


def test_no_trajectories_unless_asked():
    scene = vibro.preset("paper")
    assert vibro.simulate(scene).trajectories is None
    scene["trajectories"] = True
    assert vibro.simulate(scene).trajectories is not None
    assert vibro.simulate(scene, trajectories=False).trajectories is None


def test_summary_stats_warnings_are_plain_python_values():
    run = vibro.simulate(vibro.preset("paper"))
    assert isinstance(run.summary, dict) and isinstance(run.stats, dict)
    assert isinstance(run.warnings, list)
    assert run.summary["limiter_impacts"] == 17 and run.summary["collisions"] == 9
    assert run.answer == run.summary["answer"]
    assert run.answer.startswith("The system stops being vibro-impact after impact 27")
    assert isinstance(run.stats["steps"], int) and isinstance(run.stats["rtol"], float)
    assert run.lyapunov is None
    assert "Run" in repr(run) and "impact 27" in repr(run)


def test_lyapunov_exponents_when_the_scene_asks():
    scene = vibro.preset("impact-oscillator")
    scene["lyapunov"] = True
    run = vibro.simulate(scene)
    assert len(run.lyapunov["exponents"]) == 2
    assert_parts_are_the_jsons(run)


def test_the_deadline_stops_a_long_run():
    scene = vibro.preset("impact-oscillator")
    scene["t_end"] = 1e5
    run = vibro.simulate(scene, deadline_ms=50)
    assert run.stats["termination"] == "deadline"
    assert run.stats["t_reached"] < 1e5
    assert "deadline" in run.stats["message"] and "deadline" in run.answer
    assert_parts_are_the_jsons(run)


def test_threads_share_nothing():
    names = PRESETS[:8]
    alone = [without_wall_clock(vibro.simulate(vibro.preset(n)).to_json()) for n in names]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        together = list(pool.map(lambda n: vibro.simulate(vibro.preset(n)).to_json(), names * 2))
    assert [without_wall_clock(t) for t in together] == alone * 2


def test_threads_reading_one_run_get_its_one_summary():
    # The answer sentence is made with the GIL released: threads that read the summary of the same
    # run meanwhile all get the one dict the run keeps.
    for _ in range(20):
        run = vibro.simulate(vibro.preset("paper"))
        start = threading.Barrier(4)

        def read(_):
            start.wait()
            return run.summary

        with concurrent.futures.ThreadPoolExecutor(4) as pool:
            summaries = list(pool.map(read, range(4)))
        assert all(s is run.summary for s in summaries)
        assert run.answer == run.summary["answer"]


def test_numpy_values_in_a_scene_read_as_python_ones():
    scene = vibro.preset("paper")
    ours = vibro.preset("paper")
    ours["t_end"] = np.float64(scene["t_end"])
    ours["width"] = np.int64(scene["width"])
    ours["model"]["pellets"][0]["phi0"] = np.array(scene["model"]["pellets"][0]["phi0"])
    ours["solver"]["check"] = np.bool_(True)
    assert without_wall_clock(vibro.simulate(ours).to_json()) == without_wall_clock(
        vibro.simulate(scene).to_json()
    )
    assert math.isfinite(vibro.simulate(ours).stats["error_estimate"])


CTRL_C = textwrap.dedent(
    """
    import sys, time
    sys.path.insert(0, sys.argv[1])
    import vibro
    scene = vibro.preset("impact-oscillator")
    scene["t_end"] = 1e6  # hours of running
    print("started", flush=True)
    started = time.monotonic()
    try:
        vibro.simulate(scene)
        print("finished")
    except KeyboardInterrupt:
        print("interrupted after %.3f s" % (time.monotonic() - started), flush=True)
    """
)


def test_ctrl_c_stops_a_long_run():
    out, returncode = interrupt(CTRL_C, after=0.5)
    assert out.startswith("interrupted"), out
    assert returncode == 0
