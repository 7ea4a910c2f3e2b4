#include "render/markers.h"

#include <numbers>

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

void draw_markers(cairo_t* cr, std::span<const Point> centres, MarkerShape shape, double radius,
                  Colour fill, Colour edge, double edge_width) {
  if (centres.empty()) return;
  for (const Point& c : centres) add_marker_path(cr, c, shape, radius);
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
