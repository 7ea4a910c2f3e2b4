// Antialiased curves written straight into an image surface's pixels. cairo's stroker scans
// every row of a stroke's bounding box for every edge of its polygon: a curve across a panel
// costs it about a millisecond, most of a figure's drawing. Here each pixel within reach of a
// segment gets the share of it the line covers (a box filter across the line), a polyline's
// segments join by taking the larger coverage (round joins and caps, no double blending), and
// the pixels are blended once per polyline.
#pragma once

#include <cairo.h>

#include <span>

#include "render/geometry.h"

namespace vibro::render {

// Draws the pixel polyline with cr's solid source, line width and OVER, clipped to its clip
// rectangle, as cairo would stroke it with round joins and caps. Returns false, drawing
// nothing, where it does not apply (a vector surface, a dash, a transform, a group or
// pattern, a clip that is not one rectangle): the caller strokes with cairo.
bool raster_polyline(cairo_t* cr, std::span<const Point> pixels);

}  // namespace vibro::render
