// Polyline thinning in pixel space: drops the points whose removal moves the drawn line by less
// than a sub-pixel tolerance, so a dense trajectory costs few path vertices (fast strokes, small
// SVG) and looks the same.
#pragma once

#include <span>
#include <vector>

#include "render/geometry.h"

namespace vibro::render {

// Every input point lies within `tolerance_px` of the returned polyline, which keeps the first
// and last points. A radial pass (half the tolerance) makes it linear in dense input; a
// Ramer–Douglas–Peucker pass (the other half) then drops points on nearly straight stretches.
std::vector<Point> thin_polyline(std::span<const Point> points, double tolerance_px);

// Distance from p to the segment [a, b].
double distance_to_segment(Point p, Point a, Point b);

}  // namespace vibro::render
