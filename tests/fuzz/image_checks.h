// What the render fuzzer holds every drawn figure to: bytes that a reader of the format takes
// whole (a PNG that decodes to the figure's size, an SVG whose tags balance and close, a PDF
// from its header to its %%EOF), and plot axes that are finite and on the image.
#pragma once

#include <string>

#include "render/figure.h"

namespace vibro::fuzz {

// Empty when the figure is well formed; else what is wrong with it.
std::string image_defect(const RenderResult& image, ImageFormat format, int width, int height);

}  // namespace vibro::fuzz
