#include "io/figure_json.h"

#include "io/json_fields.h"

namespace vibro {

PrintSize read_print_size(const nlohmann::json& j) {
  Fields f(j, "figure");
  PrintSize p;
  p.width_mm = f.required_number("width_mm");
  p.height_mm = f.number("height_mm", 2.0 / 3.0 * p.width_mm);
  p.font_pt = f.number("font_pt", p.font_pt);
  p.dpi = f.number("dpi", p.dpi);
  f.done();
  return p;
}

nlohmann::json print_size_to_json(const PrintSize& p) {
  return {
      {"width_mm", p.width_mm}, {"height_mm", p.height_mm}, {"font_pt", p.font_pt}, {"dpi", p.dpi}};
}

}  // namespace vibro
