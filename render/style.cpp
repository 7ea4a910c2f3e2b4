#include "render/style.h"

#include <algorithm>
#include <cmath>

namespace vibro::render {

Style style_for(int width, int height) {
  // Text and lines grow with the geometric mean of the size, gently, so that thumbnails stay
  // legible and posters do not get toy-sized labels.
  const double relative = std::sqrt(static_cast<double>(width) * height / (1200.0 * 800.0));
  return Style{std::clamp(std::sqrt(relative), 0.75, 2.5)};
}

Style style_for(const FigureSpec& figure) {
  if (!figure.print) return style_for(figure.width, figure.height);
  // font_pt points are font_pt / 72 inches: that many dots at dpi, for a tick font of 13 px at
  // scale 1.
  const double tick_px = figure.print->font_pt / 72.0 * figure.print->dpi;
  return Style{tick_px / Style{}.tick_font(), true};
}

}  // namespace vibro::render
