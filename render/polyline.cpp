#include "render/polyline.h"

#include <algorithm>
#include <cmath>

#include "render/thin.h"

namespace vibro::render {
namespace {

constexpr std::size_t kChunk = 256;

}  // namespace

Point clamped_pixel(const Transform& tr, Point data) {
  const Rect& a = tr.area();
  const double reach = 4.0 * std::max(a.w, a.h);
  const Point q = tr.to_pixel(data.x, data.y);
  return {std::clamp(q.x, a.x - reach, a.right() + reach),
          std::clamp(q.y, a.y - reach, a.bottom() + reach)};
}

std::vector<Point> to_thinned_pixels(const Transform& tr, std::span<const Point> data,
                                     double tolerance_px) {
  std::vector<Point> pixels;
  pixels.reserve(data.size());
  for (const Point& p : data) {
    const Point q = tr.to_pixel(p.x, p.y);
    if (std::isfinite(q.x) && std::isfinite(q.y)) pixels.push_back(clamped_pixel(tr, p));
  }
  return thin_polyline(pixels, tolerance_px);
}

void stroke_polyline(cairo_t* cr, std::span<const Point> pixels) {
  if (pixels.size() < 2) return;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  // The antialiasing stays the context's (cairo's default, GRAY, on images). Not
  // CAIRO_ANTIALIAS_FAST: in cairo 1.16 it rasterises with the tor22 scan converter, whose span
  // buffer holds one span per pixel column of the area drawn, while a row whose coverage changes
  // at every column and is not zero at its right edge needs one more. A dense curve across a
  // panel makes such rows; the extra span is written past the heap block, and the process
  // aborts (issue 31; tests/render/raster_stroke_test.cpp). The tor scan converter that GRAY
  // uses allocates width + 1.
  for (std::size_t start = 0; start + 1 < pixels.size(); start += kChunk) {
    const std::size_t end = std::min(pixels.size(), start + kChunk + 1);
    cairo_move_to(cr, pixels[start].x, pixels[start].y);
    for (std::size_t i = start + 1; i < end; ++i) cairo_line_to(cr, pixels[i].x, pixels[i].y);
    cairo_stroke(cr);
  }
}

double polyline_length(std::span<const Point> pixels) {
  double length = 0.0;
  for (std::size_t i = 1; i < pixels.size(); ++i)
    length += std::hypot(pixels[i].x - pixels[i - 1].x, pixels[i].y - pixels[i - 1].y);
  return length;
}

Point point_along(std::span<const Point> pixels, double fraction, Point* direction) {
  *direction = {1.0, 0.0};
  if (pixels.empty()) return {};
  double remaining = fraction * polyline_length(pixels);
  for (std::size_t i = 1; i < pixels.size(); ++i) {
    const double dx = pixels[i].x - pixels[i - 1].x, dy = pixels[i].y - pixels[i - 1].y;
    const double step = std::hypot(dx, dy);
    if (step <= 0.0) continue;
    if (remaining <= step) {
      *direction = {dx / step, dy / step};
      const double t = remaining / step;
      return {pixels[i - 1].x + t * dx, pixels[i - 1].y + t * dy};
    }
    remaining -= step;
  }
  return pixels.back();
}

}  // namespace vibro::render
