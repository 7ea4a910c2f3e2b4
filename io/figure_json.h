// A scene's print size as JSON (API.md, "Figure size for print"): the "figure" object, read
// strictly and written back.
#pragma once

#include <nlohmann/json.hpp>

#include "render/plot_spec.h"

namespace vibro {

// Reads {"width_mm", "height_mm", "font_pt", "dpi"}: width_mm is required, height_mm is two
// thirds of the width when left out, font_pt and dpi take PrintSize's defaults. Throws
// FieldException (io/json_fields.h) naming the field ("figure.dpi"); bounds are
// check_print_size's (render/figure_size.h).
PrintSize read_print_size(const nlohmann::json& json);
nlohmann::json print_size_to_json(const PrintSize& print);

}  // namespace vibro
