#include "render/markers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_set>

#include "render/text.h"

namespace vibro::render {

void add_marker_path(cairo_t* cr, Point c, MarkerShape shape, double radius) {
  switch (shape) {
    case MarkerShape::circle:
      cairo_new_sub_path(cr);
      cairo_arc(cr, c.x, c.y, radius, 0.0, 2.0 * std::numbers::pi);
      break;
    case MarkerShape::diamond: {
      const double r = 1.3 * radius;  // same visual weight as the circle
      cairo_move_to(cr, c.x, c.y - r);
      cairo_line_to(cr, c.x + r, c.y);
      cairo_line_to(cr, c.x, c.y + r);
      cairo_line_to(cr, c.x - r, c.y);
      cairo_close_path(cr);
      break;
    }
    case MarkerShape::triangle: {
      const double r = 1.35 * radius;
      cairo_move_to(cr, c.x, c.y - r);
      cairo_line_to(cr, c.x + 0.866 * r, c.y + 0.5 * r);
      cairo_line_to(cr, c.x - 0.866 * r, c.y + 0.5 * r);
      cairo_close_path(cr);
      break;
    }
  }
}

namespace {

// The quarter-pixel cell of a point (coordinates past ±2.5e8 px share the outermost cells).
std::uint64_t cell_of(Point c) {
  const auto index = [](double v) {
    return static_cast<std::uint32_t>(
        static_cast<std::int32_t>(std::clamp(std::floor(4.0 * v), -1e9, 1e9)));
  };
  return std::uint64_t{index(c.x)} << 32 | index(c.y);
}

}  // namespace

void draw_markers(cairo_t* cr, std::span<const Point> centres, MarkerShape shape, double radius,
                  Colour fill, Colour edge, double edge_width) {
  // One marker per quarter-pixel cell: another in the same cell moves what shows by less than a
  // third of a pixel, and cairo fills a path of many overlapping markers in a time that grows
  // with the square of their number (20 000 impacts in a φ(t) panel's event row took seconds).
  std::unordered_set<std::uint64_t> cells;
  for (const Point& c : centres)
    if (std::isfinite(c.x) && std::isfinite(c.y) && cells.insert(cell_of(c)).second)
      add_marker_path(cr, c, shape, radius);
  if (cells.empty()) return;
  set_colour(cr, fill);
  if (edge_width <= 0.0) {
    cairo_fill(cr);
    return;
  }
  cairo_fill_preserve(cr);
  set_colour(cr, edge);
  cairo_set_line_width(cr, edge_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr);
}

}  // namespace vibro::render
