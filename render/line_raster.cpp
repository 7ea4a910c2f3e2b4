#include "render/line_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace vibro::render {
namespace {

// Where and what raster_polyline draws: the image's pixels, the clip, the line.
struct Canvas {
  unsigned char* data = nullptr;
  int stride = 0;
  double clip_x0 = 0.0, clip_y0 = 0.0, clip_x1 = 0.0, clip_y1 = 0.0;  // pixels, in the image
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the pixels the clip touches: [x0, x1) × [y0, y1)
  std::uint32_t alpha = 0, red = 0, green = 0, blue = 0;  // the source, 0..255, straight
  double half_width = 0.0;
};

bool identity(const cairo_matrix_t& m) {
  return m.xx == 1.0 && m.yy == 1.0 && m.xy == 0.0 && m.yx == 0.0 && m.x0 == 0.0 && m.y0 == 0.0;
}

std::uint32_t to_byte(double v) {
  return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// The canvas of cr, if the raster can stand in for cairo's stroke there. Every clip in render/
// is a panel's rectangle (clip_to), so the clip is taken to be its extents.
std::optional<Canvas> canvas_of(cairo_t* cr) {
  if (cairo_get_dash_count(cr) != 0 || cairo_get_operator(cr) != CAIRO_OPERATOR_OVER)
    return std::nullopt;
  cairo_matrix_t m;
  cairo_get_matrix(cr, &m);
  if (!identity(m)) return std::nullopt;
  cairo_surface_t* surface = cairo_get_group_target(cr);
  if (cairo_surface_get_type(surface) != CAIRO_SURFACE_TYPE_IMAGE) return std::nullopt;
  const cairo_format_t format = cairo_image_surface_get_format(surface);
  if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24) return std::nullopt;
  double ox = 0.0, oy = 0.0, sx = 1.0, sy = 1.0;
  cairo_surface_get_device_offset(surface, &ox, &oy);
  cairo_surface_get_device_scale(surface, &sx, &sy);
  if (ox != 0.0 || oy != 0.0 || sx != 1.0 || sy != 1.0) return std::nullopt;
  double r, g, b, a;
  if (cairo_pattern_get_rgba(cairo_get_source(cr), &r, &g, &b, &a) != CAIRO_STATUS_SUCCESS)
    return std::nullopt;  // not a solid colour

  Canvas c;
  cairo_surface_flush(surface);
  c.data = cairo_image_surface_get_data(surface);
  c.stride = cairo_image_surface_get_stride(surface);
  if (!c.data) return std::nullopt;
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  cairo_clip_extents(cr, &c.clip_x0, &c.clip_y0, &c.clip_x1, &c.clip_y1);
  c.clip_x0 = std::max(c.clip_x0, 0.0);
  c.clip_y0 = std::max(c.clip_y0, 0.0);
  c.clip_x1 = std::min(c.clip_x1, static_cast<double>(width));
  c.clip_y1 = std::min(c.clip_y1, static_cast<double>(height));
  c.x0 = static_cast<int>(std::floor(c.clip_x0));
  c.y0 = static_cast<int>(std::floor(c.clip_y0));
  c.x1 = static_cast<int>(std::ceil(c.clip_x1));
  c.y1 = static_cast<int>(std::ceil(c.clip_y1));
  c.alpha = to_byte(a);
  c.red = to_byte(r);
  c.green = to_byte(g);
  c.blue = to_byte(b);
  c.half_width = 0.5 * cairo_get_line_width(cr);
  return c;
}

// One byte of coverage per pixel of the image, and per row the span written since the last
// blend; kept per thread, all zero between polylines.
struct Coverage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> cells;
  std::vector<int> lo, hi;  // per row; lo > hi: untouched
  int top = 0, bottom = -1;  // the rows touched

  void fit(int w, int h) {
    if (w == width && h == height) return;
    width = w;
    height = h;
    cells.assign(static_cast<std::size_t>(w) * h, 0);
    lo.assign(h, w);
    hi.assign(h, -1);
    top = h;
    bottom = -1;
  }
};

// x·y/255 rounded, for x, y in 0..255.
std::uint32_t mul255(std::uint32_t x, std::uint32_t y) {
  const std::uint32_t t = x * y + 128;
  return (t + (t >> 8)) >> 8;
}

// The share of the pixel [x, x + 1) inside [lo, hi).
double overlap(int x, double lo, double hi) {
  return std::clamp(std::min(x + 1.0, hi) - std::max(static_cast<double>(x), lo), 0.0, 1.0);
}

// Coverage in 17 levels, as cairo's fast antialiasing gives it: the few grey levels of the
// curves' edges repeat, and the PNG encoder's Huffman codes for them stay short.
constexpr std::uint8_t kLevels[17] = {0,   16,  32,  48,  64,  80,  96,  112, 128,
                                      143, 159, 175, 191, 207, 223, 239, 255};

// Marks the pixels within reach of segment ab with the share of each the line covers.
void cover_segment(Coverage& cov, const Canvas c, Point a, Point b) {
  // c by value, and byte stores below cannot alias it: its fields stay in registers.
  if (!std::isfinite(a.x + a.y + b.x + b.y)) return;
  // Far outside the image a segment only matters through the rows and columns it crosses.
  constexpr double kFar = 1e6;
  a = {std::clamp(a.x, -kFar, kFar), std::clamp(a.y, -kFar, kFar)};
  b = {std::clamp(b.x, -kFar, kFar), std::clamp(b.y, -kFar, kFar)};
  const double half = c.half_width;
  const double reach = half + 0.5;  // a pixel centre farther from the line is not covered
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  const double ux = length > 0.0 ? dx / length : 1.0, uy = length > 0.0 ? dy / length : 0.0;
  // floor() for the clamped coordinates, without a library call.
  auto down = [](double v) { return static_cast<int>(v + 2.0 * kFar) - static_cast<int>(2.0 * kFar); };
  const int row_first = std::max(c.y0, down(std::min(a.y, b.y) - reach));
  const int row_last = std::min(c.y1 - 1, -down(-(std::max(a.y, b.y) + reach)));
  const double box_lo = std::min(a.x, b.x) - reach, box_hi = std::max(a.x, b.x) + reach;
  // The centres within reach of the line through a and b, per row: centre ± spread.
  const bool slanted = std::abs(uy) > 1e-9;
  const double slope = slanted ? ux / uy : 0.0, spread = slanted ? reach / std::abs(uy) : 0.0;
  for (int y = row_first; y <= row_last; ++y) {
    const double py = y + 0.5;
    double lo = box_lo, hi = box_hi;
    if (slanted) {
      const double centre = a.x + (py - a.y) * slope;
      lo = std::max(lo, centre - spread);
      hi = std::min(hi, centre + spread);
    }
    const int first = std::max(c.x0, down(lo - 0.5));
    const int last = std::min(c.x1 - 1, -down(-(hi - 0.5)));
    if (first > last) continue;
    const double row_share = y == c.y0 || y == c.y1 - 1 ? overlap(y, c.clip_y0, c.clip_y1) : 1.0;
    std::uint8_t* row = cov.cells.data() + static_cast<std::size_t>(y) * cov.width;
    // Along the row, the position along the segment and the signed distance across it grow by
    // fixed amounts; only past its ends is the distance to an end point's.
    const double qx = first + 0.5 - a.x, qy = py - a.y;
    double along = qx * ux + qy * uy, across = qx * uy - qy * ux;
    for (int x = first; x <= last; ++x, along += ux, across += uy) {
      double d = std::abs(across);
      if (along < 0.0 || along > length) {
        const Point& end = along < 0.0 ? a : b;
        const double ex = x + 0.5 - end.x, ey = py - end.y;
        d = std::sqrt(ex * ex + ey * ey);
      }
      // A box filter across the line: the part of [d − ½, d + ½] inside [−half, half].
      double share = std::clamp(std::min(d + 0.5, half) - std::max(d - 0.5, -half), 0.0, 1.0);
      share *= row_share;
      if (x == c.x0 || x == c.x1 - 1) share *= overlap(x, c.clip_x0, c.clip_x1);
      row[x] = std::max(row[x], kLevels[static_cast<int>(share * 16.0 + 0.5)]);
    }
    cov.lo[y] = std::min(cov.lo[y], first);
    cov.hi[y] = std::max(cov.hi[y], last);
    cov.top = std::min(cov.top, y);
    cov.bottom = std::max(cov.bottom, y);
  }
}

// Blends the source over the covered pixels (premultiplied ARGB32, OVER) and clears the
// coverage. Returns the rows touched, [first, last], or first > last.
std::pair<int, int> blend(Coverage& cov, const Canvas c) {
  const std::pair<int, int> rows{cov.top, cov.bottom};
  const std::uint32_t solid = 0xff000000u | (c.red << 16) | (c.green << 8) | c.blue;
  for (int y = cov.top; y <= cov.bottom; ++y) {
    if (cov.lo[y] > cov.hi[y]) continue;
    std::uint8_t* row = cov.cells.data() + static_cast<std::size_t>(y) * cov.width;
    auto* pixels = reinterpret_cast<std::uint32_t*>(c.data + static_cast<std::size_t>(y) * c.stride);
    const int end = cov.hi[y];
    for (int x = cov.lo[y]; x <= end; ++x) {
      if (row[x] == 0) {
        // Skip untouched cells eight at a time.
        std::uint64_t word;
        while (x + 8 <= end && (std::memcpy(&word, row + x, 8), word == 0)) x += 8;
        if (row[x] == 0) continue;
      }
      if (row[x] == 255 && c.alpha == 255) {  // the line's core: the colour itself
        row[x] = 0;
        pixels[x] = solid;
        continue;
      }
      const std::uint32_t sa = mul255(c.alpha, row[x]);
      row[x] = 0;
      const std::uint32_t keep = 255 - sa, p = pixels[x];
      const std::uint32_t pa = mul255(p >> 24, keep) + sa;
      const std::uint32_t pr = mul255((p >> 16) & 0xff, keep) + mul255(c.red, sa);
      const std::uint32_t pg = mul255((p >> 8) & 0xff, keep) + mul255(c.green, sa);
      const std::uint32_t pb = mul255(p & 0xff, keep) + mul255(c.blue, sa);
      pixels[x] = (pa << 24) | (pr << 16) | (pg << 8) | pb;
    }
    cov.lo[y] = cov.width;
    cov.hi[y] = -1;
  }
  cov.top = cov.height;
  cov.bottom = -1;
  return rows;
}

}  // namespace

bool raster_polyline(cairo_t* cr, std::span<const Point> pixels) {
  const std::optional<Canvas> canvas = canvas_of(cr);
  if (!canvas) return false;
  cairo_surface_t* surface = cairo_get_group_target(cr);
  thread_local Coverage cov;
  cov.fit(cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface));
  for (std::size_t i = 1; i < pixels.size(); ++i)
    cover_segment(cov, *canvas, pixels[i - 1], pixels[i]);
  const auto [first, last] = blend(cov, *canvas);
  if (first <= last)
    cairo_surface_mark_dirty_rectangle(surface, canvas->x0, first, canvas->x1 - canvas->x0,
                                       last - first + 1);
  cairo_new_path(cr);
  return true;
}

}  // namespace vibro::render
