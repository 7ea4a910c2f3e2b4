// Scene <-> JSON. Reading is strict: types, finiteness and unknown keys are checked, arrays and
// nesting bounded by `limits`, and the scene read is then checked against the same limits
// (validate_scene); a failure names the field. Writing gives the canonical form (every field, fixed
// order), which is also the cache key of a scene.
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>
#include <variant>

#include "core/run/validate.h"
#include "io/scene.h"

namespace vibro {

using SceneOrError = std::variant<Scene, FieldError>;

SceneOrError scene_from_json(const nlohmann::json& json, const Limits& limits = {});
SceneOrError scene_from_text(std::string_view text, const Limits& limits = {});
// The JSON of a scene's text, with its nesting bounded before parsing; for callers that edit
// it before reading (the command line's overrides).
std::variant<nlohmann::json, FieldError> parse_scene_text(std::string_view text,
                                                          const Limits& limits = {});
nlohmann::json scene_to_json(const Scene& scene);

}  // namespace vibro
