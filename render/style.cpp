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

}  // namespace vibro::render
