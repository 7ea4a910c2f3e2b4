"""vibro.periodic_orbit: `vibro orbit`'s answer, multipliers as complex numpy arrays."""

import json

import numpy as np
import pytest

import vibro
from conftest import ROOT, run_cli, without_wall_clock


@pytest.fixture(scope="module")
def orbit():
    return vibro.periodic_orbit(vibro.preset("impact-oscillator"))


def test_to_json_is_the_command_lines_output(orbit):
    _, out, _ = run_cli("orbit", "--preset", "impact-oscillator")
    assert without_wall_clock(orbit.to_json()) == without_wall_clock(out)


def test_multipliers_are_complex_arrays(orbit):
    j = json.loads(orbit.to_json())
    m = orbit.orbit["multipliers"]
    assert m.dtype == np.complex128 and len(m) == 2
    assert list(m) == [complex(x["re"], x["im"]) for x in j["orbit"]["multipliers"]]
    assert len(orbit.branch) == len(j["branch"]) > 10
    for ours, theirs in zip(orbit.branch, j["branch"]):
        assert list(ours["multipliers"]) == [complex(x["re"], x["im"]) for x in theirs["multipliers"]]
        assert ours["value"] == theirs["value"]


def test_the_parts_of_the_json(orbit):
    assert orbit.orbit["converged"] and orbit["orbit"]["converged"]
    kinds = {b["kind"] for b in orbit.bifurcations}
    assert {"period_doubling", "fold"} <= kinds
    assert isinstance(orbit.reached, bool)
    # The saved JSON also carries the scene that made it, as `vibro orbit` writes it.
    assert set(orbit.keys()) | {"scene"} == set(json.loads(orbit.to_json()))
    with pytest.raises(AttributeError):
        orbit.no_such_part
    assert "converged=True" in repr(orbit)


def test_the_branch_drawn(orbit):
    assert orbit.render().startswith(b"\x89PNG")
    assert orbit._repr_png_().startswith(b"\x89PNG")


def test_progress_and_an_orbit_alone():
    shares = []
    scene = vibro.preset("impact-oscillator")
    scene["periodic_orbit"]["continuation"]["to"] = 6.0
    found = vibro.periodic_orbit(scene, progress=shares.append)
    assert shares and shares == sorted(shares) and 0 < shares[-1] <= 1
    assert found.reached
    del scene["periodic_orbit"]["continuation"]
    alone = vibro.periodic_orbit(scene)
    assert alone.branch == [] and alone.render() is None and alone._repr_png_() is None
    assert alone.orbit["converged"]


def test_a_followed_period_doubling_gives_its_curve():
    scene = vibro.preset("impact-oscillator")
    scene["model"]["pellets"][0]["Omega"] = 6.0
    scene["periodic_orbit"] = {
        "guess": [{"phi": 0.15, "dphi": 0.1}],
        "continuation": {
            "parameter": "model.pellets[0].Omega", "to": 5.0, "max_points": 30,
            "follow": "period_doubling",
            "parameter2": {"parameter": "model.limiters[0].k", "from": 0.7, "to": 0.9}}}
    shares = []
    found = vibro.periodic_orbit(scene, progress=shares.append)
    assert shares == sorted(shares) and shares[-1] <= 1
    (curve,) = found.curves
    assert curve["kind"] == "period_doubling"
    assert curve["points"][0]["value2"] == 0.7 and curve["points"][-1]["value2"] == 0.9
    assert all(5.0 < p["value"] < 6.0 for p in curve["points"])
    assert found.render().startswith(b"\x89PNG")
    del scene["periodic_orbit"]["continuation"]["parameter2"]
    with pytest.raises(vibro.SceneError) as e:
        vibro.periodic_orbit(scene)
    assert e.value.field == "periodic_orbit.continuation.parameter2"


def test_curves_are_drawn_over_the_regime_map_as_the_command_line_draws_them(tmp_path):
    path = ROOT / "docs" / "scenes" / "impact-oscillator-pd-curve.json"
    found = vibro.periodic_orbit(json.loads(path.read_text()))
    out = tmp_path / "curves.png"
    run_cli("orbit", path, "-o", out)
    image = found.render()
    assert image == out.read_bytes()
    assert found._repr_png_() == image  # the sweep kept, not run again
    # Without the sweep the figure is the curves alone: another image.
    scene = json.loads(path.read_text())
    del scene["sweep"]
    assert vibro.periodic_orbit(scene).render() != image
