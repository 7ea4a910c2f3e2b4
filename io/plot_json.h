// A scene's `plots` (API.md): each kind created from the JSON fields it reads, and written back.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/run/limits.h"
#include "render/plot_spec.h"

namespace vibro {

// One entry of `plots` at `path` ("plots[2]"), its lists bounded by `limits`. Throws
// FieldException naming the field when a field is missing, unknown or of the wrong type; what
// its values may be is validate_plot's question (render/plot_validate.h).
PlotSpec plot_from_json(const nlohmann::json& j, const std::string& path, const Limits& limits);

// The plot as the scene reader reads it back; defaults left out.
nlohmann::json plot_to_json(const PlotSpec& plot);

}  // namespace vibro
