#include "server/scene_request.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro::server {

std::optional<double> parse_number(const std::string& text) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return {};
  return x;
}

namespace {

using nlohmann::json;

std::optional<long> parse_integer(const std::string& text) {
  long x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size()) return {};
  return x;
}

std::string joined(const std::vector<std::string_view>& names) {
  std::string list = "preset";
  for (std::string_view n : names) list += ", " + std::string(n);
  return list;
}

SceneOrApiError parsed(SceneOrError scene) {
  if (auto* e = std::get_if<FieldError>(&scene)) return ApiError::from(*e);
  return std::get<Scene>(std::move(scene));
}

// Applies one query override to the preset's JSON, or says what is wrong with its value.
std::optional<ApiError> apply_override(json& scene, const std::string& name,
                                       const std::string& value) {
  const auto bad = [&](const char* expected) {
    return ApiError{400, name, std::string("must be ") + expected + ", got \"" + value + "\""};
  };
  if (name == "t_end" || name == "rtol" || name == "atol") {
    const auto x = parse_number(value);
    if (!x) return bad("a number");
    if (name == "t_end")
      scene["t_end"] = *x;
    else
      scene["solver"][name] = *x;
  } else if (name == "width" || name == "height") {
    const auto x = parse_integer(value);
    if (!x) return bad("an integer (px)");
    scene[name] = *x;
  } else if (name == "width_mm" || name == "height_mm" || name == "font_pt" || name == "dpi") {
    // The print size (API.md): the scene's "figure" object, made when the query names one.
    const auto x = parse_number(value);
    if (!x) return bad("a number");
    scene["figure"][name] = *x;
  } else if (name == "pellet") {
    const auto x = parse_integer(value);
    if (!x) return bad("a pellet index (from 0)");
    for (json& plot : scene["plots"]) {
      const std::string kind = plot.value("kind", "");
      if (kind == "phase" || kind == "cylinder") plot["pellet"] = *x;
    }
  } else if (name == "method") {
    scene["solver"]["method"] = value;
  } else if (name == "trajectories" || name == "check") {
    if (value != "true" && value != "false") return bad("true or false");
    (name == "check" ? scene["solver"]["check"] : scene["trajectories"]) = value == "true";
  }
  return std::nullopt;
}

}  // namespace

SceneOrApiError scene_from_body(const httplib::Request& req, const vibro::Limits& limits) {
  return parsed(scene_from_text(req.body, limits));
}

SceneOrApiError scene_from_query(const httplib::Request& req, const vibro::Limits& limits,
                                 const std::vector<std::string_view>& allowed) {
  for (const auto& [name, value] : req.params) {
    if (name != "preset" && std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      return ApiError{400, name, "is not a parameter here (allowed: " + joined(allowed) + ")"};
    }
  }
  if (!req.has_param("preset")) {
    return ApiError{400, "preset", "is required: ?preset=NAME (see /api/presets)"};
  }
  const std::string name = req.get_param_value("preset");
  const auto text = preset_json(name);
  if (!text) return ApiError{404, "preset", "no preset named \"" + name + "\" (see /api/presets)"};
  json scene = json::parse(*text);
  for (const auto& [param, value] : req.params) {
    if (auto error = apply_override(scene, param, value)) return *error;
  }
  return parsed(scene_from_json(scene, limits));
}

}  // namespace vibro::server
