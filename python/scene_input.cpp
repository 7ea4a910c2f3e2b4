#include "python/scene_input.h"

#include <variant>

#include "io/scene_json.h"
#include "python/json_values.h"
#include "python/scene_error.h"

namespace vibro::python {

Scene scene_from_python(py::handle scene) {
  if (!PyDict_Check(scene.ptr()))
    raise_scene_error(
        {"scene", "must be a dict shaped as the JSON scene (API.md), not a " +
                      py::str(py::type::handle_of(scene).attr("__name__")).cast<std::string>()});
  const Limits limits;
  SceneOrError read = scene_from_json(json_from_python(scene, limits.depth), limits);
  if (auto* e = std::get_if<FieldError>(&read)) raise_scene_error(*e);
  return std::get<Scene>(std::move(read));
}

void check(const std::optional<FieldError>& error) {
  if (error) raise_scene_error(*error);
}

}  // namespace vibro::python
