#include "render/legend.h"

#include <gtest/gtest.h>

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
