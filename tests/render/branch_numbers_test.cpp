// Branch numbers keep clear of impact markers and of each other, and stay inside the plot.
#include "render/branch_numbers.h"

#include <gtest/gtest.h>

#include <algorithm>

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

// Many branches close together (the high-frequency preset's rings): the numbers keep a gap, so
// that no two read as one ("33", "27", "60", "19" drawn edge to edge read "33276019").
TEST(BranchNumbers, KeepAGapBetweenThemselves) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300));
  CairoPtr cr(cairo_create(surface.get()));
  const Rect area{0, 0, 400, 300};
  const Style style{1.0};
  std::vector<NumberedLine> lines;
  // Vertical branches 3 px apart: their numbers would stand side by side along one row.
  for (int k = 0; k < 60; ++k) {
    const double x = 40.0 + 3.0 * k;
    lines.push_back({10 + k, {{x, 40.0}, {x, 260.0}}, true});
  }
  const auto boxes = draw_branch_numbers(cr.get(), lines, area, style, {});
  ASSERT_GT(boxes.size(), 3u);
  ASSERT_LT(boxes.size(), lines.size());  // thinned: not every branch has room for its number
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Rect& a = boxes[i];
      const Rect& b = boxes[j];
      const double dx = std::max(b.x - a.right(), a.x - b.right());
      const double dy = std::max(b.y - a.bottom(), a.y - b.bottom());
      EXPECT_TRUE(dx >= 0.5 * style.note_font() - 1e-9 || dy >= 0.35 * style.note_font() - 1e-9)
          << "numbers " << i << " and " << j << " touch";
    }
}

}  // namespace
}  // namespace vibro::render
