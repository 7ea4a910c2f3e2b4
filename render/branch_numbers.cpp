#include "render/branch_numbers.h"

#include <algorithm>
#include <optional>
#include <string>

#include "render/polyline.h"
#include "render/text.h"

namespace vibro::render {
namespace {

Colour darker(Colour c, double factor) { return {c.r * factor, c.g * factor, c.b * factor, c.a}; }

}  // namespace

Colour branch_colour(int index) {
  return series_colour(static_cast<std::size_t>(std::max(0, index - 1)));
}

std::vector<Rect> draw_branch_numbers(cairo_t* cr, const std::vector<NumberedLine>& branches,
                                      const Rect& area, const Style& style,
                                      const std::vector<Rect>& keep_clear) {
  set_font(cr, style.note_font());
  std::vector<Rect> taken = keep_clear;
  const std::size_t first_number = taken.size();
  const double offset = style.px(9.0);
  // Numbers keep half a font apart (a third vertically): side by side they read as one number
  // ("33", "27", "60" as "332760" where many branches pass close together).
  const double gap_x = 0.5 * style.note_font(), gap_y = 0.35 * style.note_font();
  for (const NumberedLine& b : branches) {
    if (!b.labelled || polyline_length(b.pixels) < style.px(40.0)) continue;
    const std::string label = std::to_string(b.index);
    for (double fraction : {0.5, 0.3, 0.7}) {
      Point dir;
      const Point p = point_along(b.pixels, fraction, &dir);
      // Left of the direction of travel, then right.
      std::optional<Rect> placed;
      for (double side : {1.0, -1.0}) {
        const Point at{p.x + side * dir.y * offset, p.y - side * dir.x * offset};
        Rect box = text_box(cr, label, at, {HAlign::center, VAlign::middle});
        const bool inside = box.x >= area.x && box.right() <= area.right() && box.y >= area.y &&
                            box.bottom() <= area.bottom();
        const Rect spaced{box.x - gap_x, box.y - gap_y, box.w + 2 * gap_x, box.h + 2 * gap_y};
        const auto number = taken.begin() + static_cast<std::ptrdiff_t>(first_number);
        const bool free =
            std::none_of(taken.begin(), number, [&](const Rect& r) { return r.overlaps(box); }) &&
            std::none_of(number, taken.end(), [&](const Rect& r) { return r.overlaps(spaced); });
        if (inside && free) {
          draw_text_on_backdrop(cr, label, at, {HAlign::center, VAlign::middle},
                                darker(branch_colour(b.index), 0.8), style.px(1.5));
          placed = box;
          break;
        }
      }
      if (placed) {
        taken.push_back(*placed);
        break;
      }
    }
  }
  return {taken.begin() + static_cast<std::ptrdiff_t>(first_number), taken.end()};
}

}  // namespace vibro::render
