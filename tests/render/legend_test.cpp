#include "render/legend.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "render/cairo_ptr.h"

namespace vibro::render {
namespace {

const Rect kArea{0, 0, 400, 300};

TEST(LengthInside, ClipsSegmentsToTheBox) {
  const Rect box{10, 10, 20, 20};
  const std::vector<Point> across{{0, 20}, {100, 20}};
  EXPECT_NEAR(length_inside(box, across), 20.0, 1e-12);
  const std::vector<Point> outside{{0, 0}, {100, 0}};
  EXPECT_EQ(length_inside(box, outside), 0.0);
  const std::vector<Point> diagonal{{0, 0}, {40, 40}};
  EXPECT_NEAR(length_inside(box, diagonal), std::hypot(20.0, 20.0), 1e-12);
}

TEST(LegendBox, PrefersTopRightWhenFree) {
  const Rect box = legend_box({100, 50}, kArea, {}, 5.0);
  EXPECT_EQ(box.x, 295);
  EXPECT_EQ(box.y, 5);
}

TEST(LegendBox, AvoidsLongStraightCurves) {
  // A pellet at rest near the top: two vertices, but a long line under both top corners.
  Obstacles avoid;
  avoid.lines.push_back({{0, 20}, {400, 20}});
  avoid.lines.push_back({{300, 280}, {310, 290}});  // a short stroke at the bottom right
  const Rect box = legend_box({100, 50}, kArea, avoid, 5.0);
  EXPECT_EQ(box.y, 245);
  EXPECT_EQ(box.x, 5);
}

TEST(LegendBox, NeverHidesALabelWhenItCanAvoidIt) {
  Obstacles avoid;
  const Rect label{350, 10, 30, 12};
  avoid.boxes.push_back(label);
  avoid.lines.push_back({{0, 280}, {400, 280}});  // bottom corners busy
  avoid.lines.push_back({{0, 30}, {90, 30}});     // top left a little busy
  const Rect box = legend_box({100, 50}, kArea, avoid, 5.0);
  EXPECT_FALSE(box.overlaps(label));
  EXPECT_EQ(length_inside(box, avoid.lines[0]) + length_inside(box, avoid.lines[1]), 0.0);
  EXPECT_EQ(box.y, 5);  // top middle
}

TEST(LegendBox, FallsBackToTheMiddleOfAnEdge) {
  Obstacles avoid;
  avoid.lines.push_back({{0, 20}, {400, 20}});      // along the top
  avoid.lines.push_back({{0, 280}, {400, 280}});    // along the bottom
  avoid.lines.push_back({{300, 150}, {400, 150}});  // the right half of the middle
  const Rect box = legend_box({100, 50}, kArea, avoid, 5.0);
  EXPECT_EQ(box.x, 5);
  EXPECT_EQ(box.y, 125);
}

}  // namespace
}  // namespace vibro::render

namespace vibro::render {
namespace {

// A legend whose every place in the plot hides a curve says so, with its size; beside or above
// the plot it is drawn where the figure made room, and hides nothing there.
TEST(LegendFit, ALegendWithNoFreeCornerIsReportedAndMovedOutOfThePlot) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 700, 500));
  CairoPtr cr(cairo_create(surface.get()));
  const Style style = style_for(1200, 800);
  const Rect area{100, 150, 400, 300};
  Obstacles everywhere;
  for (double y = 160; y < 450; y += 20) everywhere.lines.push_back({{100, y}, {500, y}});
  const std::vector<LegendEntry> entries = {{"pellet 1", kInk},
                                            {"limiter impact", kInk, Swatch::marker}};
  LegendFit fit;
  watch_legends(cr.get(), &fit);
  draw_legend(cr.get(), entries, area, everywhere, style);
  EXPECT_TRUE(fit.hid_data);
  EXPECT_GT(fit.size.x, 50.0);
  EXPECT_GT(fit.size.y, 20.0);

  LegendFit beside, above;
  watch_legends(cr.get(), &beside);
  place_legends(cr.get(), LegendPlace::beside);
  draw_legend(cr.get(), entries, area, everywhere, style);
  watch_legends(cr.get(), &above);
  place_legends(cr.get(), LegendPlace::above);
  draw_legend(cr.get(), entries, area, everywhere, style);
  place_legends(cr.get(), LegendPlace::inside);
  watch_legends(cr.get(), nullptr);
  EXPECT_FALSE(beside.hid_data);
  EXPECT_FALSE(above.hid_data);
  cairo_surface_flush(surface.get());
  // Ink right of the plot (beside) and over it (above): the legends' frames and text.
  const auto* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  auto ink_in = [&](Rect r) {
    long n = 0;
    for (int y = static_cast<int>(r.y); y < static_cast<int>(r.bottom()); ++y)
      for (int x = static_cast<int>(r.x); x < static_cast<int>(r.right()); ++x)
        n += (reinterpret_cast<const std::uint32_t*>(data + y * stride)[x] & 0xffffff) != 0;
    return n;
  };
  EXPECT_GT(ink_in({area.right() + 1, area.y, 190, fit.size.y}), 100);
  EXPECT_GT(ink_in({area.right() - fit.size.x, area.y - fit.size.y - 10, fit.size.x, fit.size.y}),
            100);
}

// Above its plot a legend lays its entries in rows across the plot's width, so that it takes the
// height of as few rows as fit (it was one entry a row, a tower over a wide plot: the φ(t) panel
// of an 85 mm figure lost half its height to it); in one row when the width holds them all, one
// entry a row at a width of 0.
TEST(LegendGrid, AboveThePlotEntriesFillRowsAcrossItsWidth) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 10, 10));
  CairoPtr cr(cairo_create(surface.get()));
  const Style style = style_for(1200, 800);
  const std::vector<LegendEntry> entries = {{"pellet 1", kInk},
                                            {"pellet 2", kInk},
                                            {"limiter impact", kInk, Swatch::marker},
                                            {"collision", kInk, Swatch::marker}};
  const LegendGrid column = legend_grid(cr.get(), entries, style, 0.0);
  const LegendGrid wide = legend_grid(cr.get(), entries, style, 2000.0);
  const LegendGrid narrow = legend_grid(cr.get(), entries, style, 0.6 * wide.size.x);
  ASSERT_EQ(column.at.size(), 4u);
  EXPECT_EQ(legend_size(cr.get(), entries, style).y, column.size.y);
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_EQ(column.at[k].x, column.at[0].x);
    EXPECT_GT(column.at[k].y, column.at[k - 1].y);
    EXPECT_EQ(wide.at[k].y, wide.at[0].y);  // one row
    EXPECT_GT(wide.at[k].x, wide.at[k - 1].x);
  }
  EXPECT_LT(wide.size.y, 0.4 * column.size.y);
  EXPECT_GT(narrow.size.y, wide.size.y);  // two rows or more
  EXPECT_LT(narrow.size.y, column.size.y);
  EXPECT_LE(narrow.size.x, 0.6 * wide.size.x);
}

}  // namespace
}  // namespace vibro::render
