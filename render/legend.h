// A legend box in the corner of a plot area that hides the least of the data.
#pragma once

#include <cairo.h>

#include <span>
#include <string>
#include <vector>

#include "render/geometry.h"
#include "render/markers.h"
#include "render/style.h"

namespace vibro::render {

enum class Swatch { line, dashed_line, dotted_line, marker, area };

struct LegendEntry {
  std::string label;
  Colour colour;
  Swatch swatch = Swatch::line;
  MarkerShape marker = MarkerShape::circle;
  Colour edge{0.0, 0.0, 0.0, 0.0};  // marker or area outline; transparent: none
};

// What a legend should not hide: drawn curves (pixel polylines) and labels.
struct Obstacles {
  std::vector<std::vector<Point>> lines;
  std::vector<Rect> boxes;
};

// Length of the polyline inside the rectangle, in pixels.
double length_inside(const Rect& box, std::span<const Point> line);

// The place in `area` where a box of `size` hides the least: no label if it can, then the
// shortest length of curve. Corners are preferred (top right, top left, bottom right, bottom
// left), then the middles of the edges, then the centre. Returns the box.
Rect legend_box(Point size, const Rect& area, const Obstacles& avoid, double inset);

// The legend box's distance from the edges of the area it is drawn in, at scale 1.
inline constexpr double kLegendInset = 8.0;

// The legend box of the entries in the note font: one entry a row for a width of 0, else rows
// filled left to right as far as `width` px allow; nothing when there are none.
struct LegendGrid {
  std::vector<Point> at;  // per entry: its swatch's left middle, from the box's top left
  Point size;
};
LegendGrid legend_grid(cairo_t* cr, const std::vector<LegendEntry>& entries, const Style& style,
                       double width);

// The size of the legend box of the entries in one column (nothing when there are none).
Point legend_size(cairo_t* cr, const std::vector<LegendEntry>& entries, const Style& style);

// Draws the entries in the best corner of `area`; nothing when there are none. Beside or above
// the plot instead while the figure asks for it (place_legends).
void draw_legend(cairo_t* cr, const std::vector<LegendEntry>& entries, const Rect& area,
                 const Obstacles& avoid, const Style& style);

// What the legends drawn on cr while a fit is watched needed: whether the best corner of one
// still hid data (a curve, a mark or a label), and the largest legend's size.
struct LegendFit {
  bool hid_data = false;
  Point size;
  Point strip;  // the largest legend's size above its plot, in rows across its width
};
// Watches the legends drawn on cr from now on (null: stops).
void watch_legends(cairo_t* cr, LegendFit* fit);
// Where legends go: in the best corner of their plot area, or where the figure has made room
// for a panel whose legend would hide data in every corner: right of the plot, top aligned, or
// above it, right aligned, its entries in rows across the plot's width.
enum class LegendPlace { inside, beside, above };
void place_legends(cairo_t* cr, LegendPlace place);

}  // namespace vibro::render
