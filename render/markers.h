// Point markers (impacts, collisions): all markers of one kind go into one path and one fill.
#pragma once

#include <cairo.h>

#include <span>

#include "render/geometry.h"
#include "render/style.h"

namespace vibro::render {

enum class MarkerShape { circle, diamond, triangle };

// Adds the marker's outline, `radius` pixels from its centre, to the current path.
void add_marker_path(cairo_t* cr, Point centre, MarkerShape shape, double radius);

// Fills markers at every point and outlines them in `edge` (`edge_width` px; 0: no outline):
// one marker per quarter-pixel cell, points that are not finite skipped.
void draw_markers(cairo_t* cr, std::span<const Point> centres, MarkerShape shape, double radius,
                  Colour fill, Colour edge, double edge_width);

}  // namespace vibro::render
