// A scene handed to the module, read as the command line reads a scene file: its dict converted to
// JSON (python/json_values.h) and read by io/scene_json.h under the command line's limits
// (Limits{}), so the same scene gives the same doubles, and a bad one the same field and message.
#pragma once

#include <pybind11/pybind11.h>

#include "io/scene.h"

namespace vibro::python {

namespace py = pybind11;

// Raises SceneError naming the field, or "scene" when `scene` is not a dict.
Scene scene_from_python(py::handle scene);

// Raises SceneError when `error` holds one.
void check(const std::optional<FieldError>& error);

}  // namespace vibro::python
