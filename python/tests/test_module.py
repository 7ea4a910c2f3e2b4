"""The package itself: which build it comes from, its names, the presets."""

import json

import vibro
from conftest import BUILD, module_is_built_one, run_cli


def test_the_tests_import_the_build_not_an_installed_copy():
    assert module_is_built_one(), f"{vibro.__file__} is not under {BUILD}/python"


def test_the_names_of_api_md():
    for name in ("simulate", "render", "sweep", "periodic_orbit", "presets", "preset", "SceneError"):
        assert hasattr(vibro, name), name
    assert issubclass(vibro.SceneError, ValueError)


def test_presets_list_as_the_command_line():
    _, out, _ = run_cli("presets")
    assert vibro.presets() == json.loads(out)
    assert vibro.presets()[0]["name"] == "paper"


def test_every_preset_is_the_command_lines_dict():
    for p in vibro.presets():
        _, out, _ = run_cli("preset", p["name"])
        assert vibro.preset(p["name"]) == json.loads(out)


def test_an_unknown_preset_names_the_field():
    try:
        vibro.preset("no-such")
    except vibro.SceneError as e:
        assert e.field == "preset"
        assert "no-such" in e.message
    else:
        raise AssertionError("no SceneError")
