// Curves from data to cairo: data points to pixels, thinning at sub-pixel tolerance, and
// stroking in chunks (cairo's stroker slows down sharply on long self-intersecting paths).
#pragma once

#include <cairo.h>

#include <span>
#include <vector>

#include "render/geometry.h"
#include "render/transform.h"

namespace vibro::render {

// Thinning tolerance: a quarter pixel does not change the antialiased line visibly.
inline constexpr double kThinTolerancePx = 0.25;

// A data point as a pixel, clamped to four times the plot area's size beyond its edges: cairo's
// fixed-point arithmetic never overflows on what leaves the area, and a dashed line to a point
// far outside (an axis range far narrower than the data) costs a bounded number of dashes,
// which a vector surface would otherwise keep every one of. Exact for a segment parallel to an
// axis; a curve's clamped points move only where it is outside the area.
Point clamped_pixel(const Transform& tr, Point data);

// Data points to pixels (clamped_pixel), thinned; points that are not finite are dropped.
std::vector<Point> to_thinned_pixels(const Transform& tr, std::span<const Point> data,
                                     double tolerance_px = kThinTolerancePx);

// Strokes the pixel polyline with the current source, width and dash, a few hundred vertices
// per stroke; round joins and caps hide the seams between chunks.
void stroke_polyline(cairo_t* cr, std::span<const Point> pixels);

// Total length in pixels.
double polyline_length(std::span<const Point> pixels);

// The point at `fraction` (0..1) of the polyline's length, and the unit direction there.
Point point_along(std::span<const Point> pixels, double fraction, Point* direction);

}  // namespace vibro::render
