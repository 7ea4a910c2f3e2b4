// Branch numbers keep clear of impact markers and of each other, and stay inside the plot.
#include "render/branch_numbers.h"

#include <gtest/gtest.h>

#include "render/cairo_ptr.h"

namespace vibro::render {
namespace {

TEST(BranchNumbers, KeepClearOfMarkers) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300));
  CairoPtr cr(cairo_create(surface.get()));
  const Rect area{0, 0, 400, 300};
  const Style style{1.0};
  const std::vector<NumberedLine> line{{3, {{50, 150}, {350, 150}}, true}};

  const auto free = draw_branch_numbers(cr.get(), line, area, style, {});
  ASSERT_EQ(free.size(), 1u);  // beside the middle, with nothing in the way
  const Rect middle = free[0];
  EXPECT_NEAR(middle.x + middle.w / 2, 200.0, 1.0);

  // A marker over both sides of the middle: the number moves along the branch.
  const Rect marker{middle.x - 4, 130, middle.w + 8, 40};
  const auto moved = draw_branch_numbers(cr.get(), line, area, style, {marker});
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_FALSE(moved[0].overlaps(marker));
  EXPECT_TRUE(area.contains({moved[0].x, moved[0].y}));

  // An unlabelled piece gets no number.
  const std::vector<NumberedLine> piece{{3, {{50, 150}, {350, 150}}, false}};
  EXPECT_TRUE(draw_branch_numbers(cr.get(), piece, area, style, {}).empty());
}

}  // namespace
}  // namespace vibro::render
