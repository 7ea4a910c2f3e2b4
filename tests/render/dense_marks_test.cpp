// Thousands of impacts drawn where few pixels hold them (issue 31's render fuzzer: a run of
// 20 000 impacts took seconds to draw as PNG, cairo filling and stroking the overlapping marks
// in a time that grows with the square of their number): markers in one quarter-pixel cell are
// drawn once, and the jumps at one angle merged where they overlap.
#include <cairo-svg.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/cairo_ptr.h"
#include "render/markers.h"
#include "render/phase_jumps.h"
#include "svg_check.h"

namespace vibro::render {
namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// The SVG of 20 000 circle markers along 50 px of one row.
std::string svg_of_dense_markers() {
  std::string svg;
  {
    SurfacePtr surface(cairo_svg_surface_create_for_stream(append, &svg, 200, 100));
    CairoPtr cr(cairo_create(surface.get()));
    std::vector<Point> centres;
    for (int i = 0; i < 20000; ++i) centres.push_back({10.0 + 50.0 * i / 20000.0, 50.0});
    draw_markers(cr.get(), centres, MarkerShape::circle, 3.0, Colour{0, 0, 0, 1}, Colour{}, 0.0);
  }
  return svg;
}

TEST(DenseMarks, MarkersInOneQuarterPixelCellAreDrawnOnce) {
  const std::string svg = svg_of_dense_markers();
  // Each circle starts a sub-path with a move-to: 50 px hold 200 quarter-pixel cells.
  EXPECT_LE(testing::count_of(svg, "M "), 201);
  EXPECT_GE(testing::count_of(svg, "M "), 190);
}

TEST(DenseMarks, JumpsAtOneAngleMergeWhereTheyOverlap) {
  const Transform tr({0, 0, 400, 300}, {-1.0, 1.0}, {-10.0, 10.0});
  std::vector<Jump> jumps;
  for (int i = 0; i < 5000; ++i)  // at φ = 0.5, each overlapping the next: one line
    jumps.push_back({{0.5, -5.0 + 1e-3 * i}, {0.5, 1e-3 * i}, nullptr});
  jumps.push_back({{-0.5, 1.0}, {-0.5, 2.0}, nullptr});  // at φ = -0.5, apart: two lines
  jumps.push_back({{-0.5, 4.0}, {-0.5, 3.0}, nullptr});
  const auto lines = jump_lines(jumps, tr);
  ASSERT_EQ(lines.size(), 3u);
  const Point lo = tr.to_pixel(0.5, -5.0), hi = tr.to_pixel(0.5, 4.999);
  const VerticalLine& merged = lines[0].x == lo.x ? lines[0] : lines[2];
  EXPECT_DOUBLE_EQ(merged.top, hi.y);  // pixel y grows downward
  EXPECT_DOUBLE_EQ(merged.bottom, lo.y);
}

}  // namespace
}  // namespace vibro::render
