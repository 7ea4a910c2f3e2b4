// vibro.SceneError (a ValueError): a scene or request the engine refuses. `.field` names the field
// as the scene's JSON spells it ("model.pellets[0].m", "sweep.count", "preset"), `.message` is the
// message of the HTTP 400 answer's body ({"error": message, "field": field}); str() joins them.
#pragma once

#include <pybind11/pybind11.h>

#include "core/run/validate.h"

namespace vibro::python {

[[noreturn]] void raise_scene_error(const FieldError& error);

}  // namespace vibro::python
