// Python values <-> JSON values (nlohmann::json), exactly: a float is the same double both ways
// (no text in between), an int stays an integer, a dict's keys are strings.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace vibro::python {

namespace py = pybind11;

// The JSON of a scene given as Python values: dicts with str keys, lists and tuples, str, bool,
// int, float and None, and numpy's scalars and arrays (as their tolist()). An int too large for
// 64 bits becomes a double, as in JSON text. Raises SceneError naming the field of a value JSON
// cannot hold, as the scene spells it ("model.pellets[0].m"), and "scene" for nesting deeper
// than `max_depth` levels (as io/scene_json.h says for text; it also ends a dict that holds
// itself).
nlohmann::json json_from_python(py::handle value, int max_depth);

// The Python values of a JSON value: dict, list, str, bool, int, float, None.
py::object python_from_json(const nlohmann::json& json);

}  // namespace vibro::python
