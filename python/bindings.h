// The pieces of the `vibro` Python module (module.cpp puts them together), one function each:
// simulate and its Run, render, sweep and its Sweep, periodic_orbit and its PeriodicOrbit, the
// presets. Each calls the same io/, core/ and render/ functions as the command line's subcommand
// of the same name (app/), so its numbers are the command line's, bit for bit.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace vibro::python {

namespace py = pybind11;

void add_scene_error(py::module_& m);
void add_simulate(py::module_& m);
void add_render(py::module_& m);
void add_sweep(py::module_& m);
void add_periodic_orbit(py::module_& m);
void add_presets(py::module_& m);

}  // namespace vibro::python
