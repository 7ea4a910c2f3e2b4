// The scene a request names: a JSON body (POST), or a preset with simple overrides in the query
// (GET, so an <img src> or a curl line can ask for it). Errors name the field or the parameter.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "io/scene.h"
#include "server/api_error.h"
#include "server/http.h"

namespace vibro::server {

using SceneOrApiError = std::variant<Scene, ApiError>;

// A query parameter's finite number, written whole (std::from_chars); nothing otherwise.
std::optional<double> parse_number(const std::string& text);

// The body as a scene: 400 naming "scene" for bad JSON, else the field at fault.
SceneOrApiError scene_from_body(const httplib::Request& req, const vibro::Limits& limits);

// "?preset=NAME" with overrides of simple fields: t_end, method, rtol, atol, width, height,
// pellet (every phase and cylinder plot draws that pellet) and trajectories. Only parameters in
// `allowed` are accepted ("preset" always is); any other is an error naming it. An unknown
// preset is a 404 naming "preset".
SceneOrApiError scene_from_query(const httplib::Request& req, const vibro::Limits& limits,
                                 const std::vector<std::string_view>& allowed);

}  // namespace vibro::server
