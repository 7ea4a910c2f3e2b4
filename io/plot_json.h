// A scene's `plots` (API.md): each kind created from the JSON fields it reads, and written back.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "render/plot_spec.h"

namespace vibro {

// One entry of `plots` at `path` ("plots[2]"), for a model of `pellets` pellets and a run to
// `t_end` s. Throws FieldException naming the field.
PlotSpec plot_from_json(const nlohmann::json& j, const std::string& path, int pellets,
                        double t_end);

// The plot as the scene reader reads it back; defaults left out.
nlohmann::json plot_to_json(const PlotSpec& plot);

}  // namespace vibro
