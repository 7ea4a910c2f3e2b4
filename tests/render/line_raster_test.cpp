// The raster that draws curves on images (render/line_raster.h) against cairo's own stroke of
// the same polyline, and against the area a line of known width and length covers.
#include "render/line_raster.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace vibro::render {
namespace {

constexpr int kW = 200, kH = 120;

struct Image {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kW, kH);
  cairo_t* cr = cairo_create(surface);
  Image() {
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
  }
  ~Image() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  std::uint32_t at(int x, int y) {
    cairo_surface_flush(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    return reinterpret_cast<const std::uint32_t*>(data + y * cairo_image_surface_get_stride(surface))[x];
  }
  // Darkness of the blue-free channel: how much ink of a pure blue line covers a pixel, 0..1.
  double ink(int x, int y) { return 1.0 - ((at(x, y) >> 16) & 0xff) / 255.0; }
  double total_ink() {
    double sum = 0.0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) sum += ink(x, y);
    return sum;
  }
};

void set_line(cairo_t* cr, double width, double alpha = 1.0) {
  cairo_set_source_rgba(cr, 0.0, 0.0, 1.0, alpha);
  cairo_set_line_width(cr, width);
}

void cairo_polyline(cairo_t* cr, const std::vector<Point>& points) {
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_BEST);
  cairo_move_to(cr, points[0].x, points[0].y);
  for (const Point& p : points) cairo_line_to(cr, p.x, p.y);
  cairo_stroke(cr);
}

TEST(LineRaster, CoversTheAreaOfTheLine) {
  // A straight line of width w and length L with round caps covers w·L + π(w/2)².
  for (double width : {1.0, 1.5, 3.0}) {
    Image img;
    set_line(img.cr, width);
    ASSERT_TRUE(raster_polyline(img.cr, std::vector<Point>{{20.3, 40.7}, {170.9, 75.2}}));
    const double length = std::hypot(170.9 - 20.3, 75.2 - 40.7);
    const double area = width * length + std::numbers::pi * width * width / 4.0;
    EXPECT_NEAR(img.total_ink(), area, 0.03 * area) << "width " << width;
  }
}

TEST(LineRaster, MatchesCairosStroke) {
  // A curve with sharp and gentle turns: pixel by pixel within an antialiased edge's difference,
  // and the same ink overall.
  std::vector<Point> curve;
  for (int i = 0; i <= 60; ++i) {
    const double t = i / 60.0;
    curve.push_back({10.0 + 180.0 * t, 60.0 + 40.0 * std::sin(9.0 * t) * std::cos(3.0 * t)});
  }
  curve.push_back({120.0, 20.0});  // a hairpin back
  Image ours, theirs;
  set_line(ours.cr, 1.5);
  set_line(theirs.cr, 1.5);
  ASSERT_TRUE(raster_polyline(ours.cr, curve));
  cairo_polyline(theirs.cr, curve);
  double worst = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) worst = std::max(worst, std::abs(ours.ink(x, y) - theirs.ink(x, y)));
  EXPECT_LT(worst, 0.35);
  EXPECT_NEAR(ours.total_ink(), theirs.total_ink(), 0.03 * theirs.total_ink());
}

TEST(LineRaster, JoinsDoNotBlendTwice) {
  // A translucent polyline folding back on itself at each vertex: no pixel gets more than one
  // layer of its colour, as in a single stroke.
  Image img;
  set_line(img.cr, 4.0, 0.5);
  ASSERT_TRUE(raster_polyline(img.cr, std::vector<Point>{{20, 20}, {100, 60}, {30, 70}, {150, 90}}));
  double most = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) most = std::max(most, img.ink(x, y));
  EXPECT_NEAR(most, 0.5, 1.0 / 255.0 + 1e-9);
}

TEST(LineRaster, StaysInsideTheClip) {
  Image img;
  cairo_rectangle(img.cr, 50.5, 30.25, 80.0, 40.0);
  cairo_clip(img.cr);
  set_line(img.cr, 2.0);
  ASSERT_TRUE(raster_polyline(img.cr, std::vector<Point>{{0, 0}, {200, 120}, {0, 120}, {200, 0}}));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool outside = x + 1 <= 50.5 || x >= 130.5 || y + 1 <= 30.25 || y >= 70.25;
      if (outside) ASSERT_EQ(img.at(x, y), 0xffffffffu) << x << ", " << y;
    }
  EXPECT_GT(img.ink(90, 54), 0.9);  // the diagonal's middle is drawn
}

TEST(LineRaster, LeavesToCairoWhatItDoesNotDraw) {
  const std::vector<Point> line{{10, 10}, {100, 50}};
  {
    Image img;
    set_line(img.cr, 1.0);
    const double dash[] = {3.0, 3.0};
    cairo_set_dash(img.cr, dash, 2, 0.0);
    EXPECT_FALSE(raster_polyline(img.cr, line));
  }
  {
    Image img;
    set_line(img.cr, 1.0);
    cairo_scale(img.cr, 2.0, 2.0);
    EXPECT_FALSE(raster_polyline(img.cr, line));
  }
  {
    Image img;
    cairo_pattern_t* gradient = cairo_pattern_create_linear(0, 0, 100, 0);
    cairo_set_source(img.cr, gradient);
    cairo_pattern_destroy(gradient);
    EXPECT_FALSE(raster_polyline(img.cr, line));
  }
  {
    cairo_surface_t* svg = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
    cairo_t* cr = cairo_create(svg);
    set_line(cr, 1.0);
    EXPECT_FALSE(raster_polyline(cr, line));
    cairo_destroy(cr);
    cairo_surface_destroy(svg);
  }
}

TEST(LineRaster, IgnoresPointsThatAreNotFinite) {
  Image img;
  set_line(img.cr, 1.5);
  const double nan = std::nan("");
  ASSERT_TRUE(raster_polyline(img.cr, std::vector<Point>{{10, 10}, {nan, 50}, {1e300, -1e300}, {60, 60}, {90, 20}}));
  EXPECT_GT(img.ink(75, 40), 0.5);  // the finite last segment is drawn
}

}  // namespace
}  // namespace vibro::render
