// An RGBA8 Image (straight alpha) as a cairo image surface (premultiplied ARGB32), to composite
// a raster panel into a figure.
#pragma once

#include "render/cairo_ptr.h"
#include "render/image.h"

namespace vibro::render {

// Null when the image is empty or its pixel buffer does not match its size.
SurfacePtr surface_from_image(const Image& image);

}  // namespace vibro::render
