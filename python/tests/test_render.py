"""vibro.render: the bytes `vibro render` writes, as an Image a notebook shows."""

import re

import pytest

import vibro
from conftest import run_cli


def same_figure(ours, theirs):
    """Equal bytes; in an SVG, up to the number cairo gives its surface, which counts the
    surfaces the process made before (as in the server)."""
    if ours.startswith(b"<?xml"):
        ours, theirs = (re.sub(rb'id="surface[0-9]+"', b'id="surface"', x) for x in (ours, theirs))
    return ours == theirs


@pytest.mark.parametrize("name", ["paper", "paper-fig1", "impact-oscillator"])
@pytest.mark.parametrize("format", ["png", "svg"])
def test_the_bytes_of_the_command_line(name, format, tmp_path):
    image = vibro.render(vibro.preset(name), format=format)
    out = tmp_path / f"figure.{format}"
    run_cli("render", "--preset", name, "-o", out)
    assert same_figure(image, out.read_bytes())
    assert isinstance(image, bytes) and image.format == format


def test_a_pdf():
    image = vibro.render(vibro.preset("paper"), format="pdf")
    assert image.startswith(b"%PDF") and image.format == "pdf"
    assert image._repr_png_() is None and image._repr_svg_() is None


def test_a_notebook_shows_png_and_svg(tmp_path):
    png = vibro.render(vibro.preset("paper"))
    assert png._repr_png_().startswith(b"\x89PNG") and png._repr_svg_() is None
    svg = vibro.render(vibro.preset("paper"), "svg")
    assert svg._repr_svg_().lstrip().startswith("<?xml") and svg._repr_png_() is None
    png.save(tmp_path / "p.png")
    assert (tmp_path / "p.png").read_bytes() == png


def test_a_figure_error_names_its_field():
    scene = vibro.preset("paper")
    scene["width"] = 10**6
    with pytest.raises(vibro.SceneError) as e:
        vibro.render(scene)
    assert e.value.field == "width"
