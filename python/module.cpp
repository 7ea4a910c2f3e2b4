// vibro._vibro: the compiled part of the `vibro` package (python/vibro/__init__.py re-exports it).
#include "python/bindings.h"

PYBIND11_MODULE(_vibro, m) {
  using namespace vibro::python;
  m.doc() =
      "vibro's engine from Python: simulate, render, sweep, periodic_orbit over scenes given as "
      "dicts shaped as the JSON scene (API.md); results hold numpy arrays.";
  add_scene_error(m);
  add_presets(m);
  add_simulate(m);
  add_render(m);
  add_sweep(m);
  add_periodic_orbit(m);
}
