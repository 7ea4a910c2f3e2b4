"""vibro from Python: the engine of the `vibro` command, over scenes given as dicts.

    import vibro
    scene = vibro.preset("paper")            # a dict shaped as the JSON scene (API.md)
    run = vibro.simulate(scene)              # events, summary, stats, warnings
    run.events["t"]                          # numpy arrays, one per column of the events' CSV
    vibro.render(scene, format="png")        # an Image: bytes a notebook shows
    vibro.sweep(vibro.preset("impact-oscillator")).points["dphi"]
    vibro.periodic_orbit(vibro.preset("impact-oscillator")).orbit["multipliers"]

The numbers are the command line's for the same scene, bit for bit; a bad scene raises
vibro.SceneError with the field it names (.field) and the message (.message). docs/PYTHON.md.
"""

from ._vibro import (
    PeriodicOrbit,
    Run,
    SceneError,
    Sweep,
    periodic_orbit,
    preset,
    presets,
    render,
    simulate,
    sweep,
)

__all__ = [
    "Image",
    "PeriodicOrbit",
    "Run",
    "SceneError",
    "Sweep",
    "periodic_orbit",
    "preset",
    "presets",
    "render",
    "simulate",
    "sweep",
]


class Image(bytes):
    """A drawn figure: the bytes of a PNG, SVG or PDF file (.format says which), shown by a
    notebook when it is a PNG or an SVG."""

    def __new__(cls, data, format):
        image = super().__new__(cls, data)
        image.format = format
        return image

    def _repr_png_(self):
        return bytes(self) if self.format == "png" else None

    def _repr_svg_(self):
        return self.decode("utf-8") if self.format == "svg" else None

    def save(self, path):
        """Writes the image to the file `path`."""
        with open(path, "wb") as f:
            f.write(self)

    def __repr__(self):
        return f"<vibro.Image: {self.format}, {len(self)} bytes>"
