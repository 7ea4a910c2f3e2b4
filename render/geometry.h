// Points, rectangles and value ranges shared by the drawing pipeline. Pixel space has y downward.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibro::render {

struct Point {
  double x = 0.0;
  double y = 0.0;
};

struct Rect {
  double x = 0.0;
  double y = 0.0;
  double w = 0.0;
  double h = 0.0;

  double right() const { return x + w; }
  double bottom() const { return y + h; }
  bool contains(Point p) const { return p.x >= x && p.x <= right() && p.y >= y && p.y <= bottom(); }
  bool overlaps(const Rect& o) const {
    return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
  }
};

// A closed interval of data values. Default-constructed it is empty and grows with include().
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  bool empty() const { return !(lo <= hi); }
  double span() const { return hi - lo; }
  bool contains(double v) const { return v >= lo && v <= hi; }
  void include(double v) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
};

// The range widened by `fraction` of its span on each side; a degenerate range gets a unit span
// (or one relative to its magnitude) so that an axis can still be drawn.
inline Range padded(Range r, double fraction) {
  if (r.empty()) return {-1.0, 1.0};
  if (r.span() <= 1e-12 * std::max(1.0, std::abs(r.lo))) {
    const double half = std::max(0.5, 0.1 * std::abs(r.lo));
    return {r.lo - half, r.hi + half};
  }
  const double pad = fraction * r.span();
  return {r.lo - pad, r.hi + pad};
}

}  // namespace vibro::render
