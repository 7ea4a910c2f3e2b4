// Data coordinates to pixels inside a plot area (ImPlot's "transformer"): x to the right, data y
// upward, pixel y downward.
#pragma once

#include "render/geometry.h"

namespace vibro::render {

class Transform {
 public:
  Transform(Rect area, Range x, Range y) : area_(area), x_(x), y_(y) {}

  double px(double x) const { return area_.x + (x - x_.lo) / x_.span() * area_.w; }
  double py(double y) const { return area_.bottom() - (y - y_.lo) / y_.span() * area_.h; }
  Point to_pixel(double x, double y) const { return {px(x), py(y)}; }

  const Rect& area() const { return area_; }
  const Range& x_range() const { return x_; }
  const Range& y_range() const { return y_; }

 private:
  Rect area_;
  Range x_;
  Range y_;
};

}  // namespace vibro::render
