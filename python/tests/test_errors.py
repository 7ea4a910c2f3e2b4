"""vibro.SceneError: the field and the message the command line and the HTTP 400 answer give."""

import json
import math

import pytest

import vibro
from conftest import cli_error


def scene_error(call, *args, **kwargs):
    with pytest.raises(vibro.SceneError) as caught:
        call(*args, **kwargs)
    e = caught.value
    assert str(e) == f"{e.field}: {e.message}"
    return e


def paper_with(edit):
    scene = vibro.preset("paper")
    edit(scene)
    return scene


BAD_SCENES = {
    "unknown field": {"model": {"R": 0.5, "alpah0": 0.1, "pellets": [{"m": 1, "phi0": 0}]}, "t_end": 1},
    "negative radius": paper_with(lambda s: s["model"].update(R=-1.0)),
    "a string for a number": paper_with(lambda s: s["model"]["pellets"][1].update(m="heavy")),
    "an unknown method": paper_with(lambda s: s["solver"].update(method="euler")),
    "no pellets": paper_with(lambda s: s["model"].update(pellets=[])),
    "a pellet out of range": paper_with(lambda s: s["plots"][0].update(pellet=7)),
    "t_end zero": paper_with(lambda s: s.update(t_end=0)),
    "a bad sweep": paper_with(lambda s: s.update(sweep={"parameter": "model.nothing", "from": 0, "to": 1})),
    "a list for the model": {"model": [], "t_end": 1},
}


@pytest.mark.parametrize("what", BAD_SCENES)
def test_the_field_and_message_of_the_command_line(what, scene_file):
    scene = BAD_SCENES[what]
    expected = cli_error("simulate", scene_file(scene))
    e = scene_error(vibro.simulate, scene)
    assert {"field": e.field, "error": e.message} == expected


def test_a_non_finite_number_names_its_field():
    e = scene_error(vibro.simulate, paper_with(lambda s: s["model"].update(R=math.nan)))
    assert e.field == "model.R" and "finite" in e.message
    e = scene_error(vibro.simulate, paper_with(lambda s: s.update(t_end=math.inf)))
    assert e.field == "t_end"


def test_what_json_cannot_hold_names_its_place():
    e = scene_error(vibro.simulate, paper_with(lambda s: s["model"]["pellets"][1].update(m=object())))
    assert e.field == "model.pellets[1].m" and "object" in e.message
    e = scene_error(vibro.simulate, paper_with(lambda s: s["model"].update({1: 2})))
    assert e.field == "model" and "not a string" in e.message
    e = scene_error(vibro.simulate, "paper")
    assert e.field == "scene"
    # A str UTF-8 cannot hold (a lone surrogate), as a value and as a key.
    e = scene_error(vibro.simulate, paper_with(lambda s: s.update(name="\ud800")))
    assert e.field == "name" and "surrogate" in e.message
    e = scene_error(vibro.simulate, paper_with(lambda s: s["model"].update({"\ud800": 1})))
    assert e.field == "model" and "surrogate" in e.message


def test_nesting_is_bounded_as_for_text(scene_file):
    deep = paper_with(lambda s: s.update(description=[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]))
    message = scene_error(vibro.simulate, deep).message
    assert message == "nests deeper than 16 levels"
    # The command line names the file it read first.
    assert cli_error("simulate", scene_file(deep))["error"].endswith(" " + message)
    looped = vibro.preset("paper")
    looped["model"]["self"] = looped
    assert scene_error(vibro.simulate, looped).field == "scene"


def test_every_entry_point_checks_its_scene():
    bad = paper_with(lambda s: s["model"].update(R=-1.0))
    for call in (vibro.simulate, vibro.render, vibro.sweep, vibro.periodic_orbit):
        assert scene_error(call, bad).field == "model.R"


def test_the_arguments_name_themselves():
    assert scene_error(vibro.render, vibro.preset("paper"), format="gif").field == "format"
    assert scene_error(vibro.sweep, vibro.preset("paper")).field == "sweep"
    assert scene_error(vibro.sweep, vibro.preset("impact-oscillator"), threads=0).field == "threads"
    assert scene_error(vibro.simulate, vibro.preset("paper"), deadline_ms=-1).field == "deadline_ms"


def test_an_orbit_request_names_its_field(scene_file):
    scene = vibro.preset("impact-oscillator")
    scene["periodic_orbit"]["periods"] = 0
    expected = cli_error("orbit", scene_file(scene))
    e = scene_error(vibro.periodic_orbit, scene)
    assert {"field": e.field, "error": e.message} == expected


def test_the_message_is_the_http_answers():
    # The server answers {"error", "field"} from the same FieldError (server/api_error.h): the
    # README's example, word for word.
    scene = json.loads('{"model":{"R":0.5,"alpah0":0.1,"pellets":[{"m":1,"phi0":0}]},"t_end":1}')
    e = scene_error(vibro.simulate, scene)
    assert e.field == "model.alpah0"
    assert e.message.startswith("is not a known field here")


@pytest.fixture(scope="module")
def server():
    """`vibro serve` of the same build on a free loopback port: its base URL."""
    import socket
    import subprocess
    import time
    import urllib.request

    from conftest import BUILD

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    process = subprocess.Popen(
        [str(BUILD / "vibro"), "serve", "--port", str(port), "--quiet", "--threads", "1"],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    base = f"http://127.0.0.1:{port}"
    try:
        for _ in range(300):
            try:
                urllib.request.urlopen(base + "/api/health", timeout=1)
                break
            except OSError:
                time.sleep(0.05)
        yield base
    finally:
        process.terminate()
        process.wait(timeout=30)


# The server tightens the command line's limits (t_end at most 1000 s by default): a message that
# names a bound names the module's, which are the command line's.
@pytest.mark.parametrize("what", [w for w in BAD_SCENES if w != "t_end zero"])
def test_the_body_of_the_http_400_answer(what, server):
    import urllib.error
    import urllib.request

    scene = BAD_SCENES[what]
    request = urllib.request.Request(
        server + "/api/simulate",
        data=json.dumps(scene).encode(),
        headers={"Content-Type": "application/json"},
    )
    with pytest.raises(urllib.error.HTTPError) as answer:
        urllib.request.urlopen(request, timeout=60)
    assert answer.value.code == 400
    e = scene_error(vibro.simulate, scene)
    assert json.loads(answer.value.read()) == {"error": e.message, "field": e.field}
