// A limiter's label never lies on the data: where a curve or a marker takes the place beside the
// top of its line, the label moves down the line to the first free place (the paper scene's
// "limiter 1 (mobile)" lay on pellet 1's impact marker and "limiter 2" on pellet 2's branch 7 at
// 170 mm), and it stays off its neighbours' lines as before.
#include <gtest/gtest.h>

#include "render/legend.h"
#include "render/limiter_lines.h"

namespace vibro::render {
namespace {

TEST(LimiterLabels, StayOffTheDataMovingDownTheLine) {
  auto surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 600, 400);
  cairo_t* cr = cairo_create(surface);
  const Transform tr({50, 20, 500, 350}, {-1.0, 1.0}, {-10.0, 10.0});
  const std::vector<LimiterLine> lines = {{0.0, 0, true}};
  const Style style;
  Obstacles data;
  // A curve across the top on both sides of the line, and a marker just below it on the right.
  data.lines.push_back({{60, 30}, {540, 30}, {540, 34}, {60, 34}});
  data.boxes.push_back({300, 40, 60, 20});
  const std::vector<Rect> free_of_data =
      draw_limiter_labels(cr, tr, lines, Orientation::vertical, style, data);
  ASSERT_EQ(free_of_data.size(), 1u);
  const Rect& label = free_of_data[0];
  EXPECT_EQ(length_inside(label, data.lines[0]), 0.0);
  EXPECT_FALSE(label.overlaps(data.boxes[0]));
  EXPECT_GT(label.y, 34.0);  // below the curve, not beside the top where it was
  // Without data the label stands beside the top of its line, as it always did.
  const std::vector<Rect> alone = draw_limiter_labels(cr, tr, lines, Orientation::vertical, style);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_LT(alone[0].y, 30.0);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

}  // namespace
}  // namespace vibro::render
