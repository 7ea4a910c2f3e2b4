#include "render/thin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vibro::render {
namespace {

double distance_to_polyline(Point p, const std::vector<Point>& line) {
  double best = std::hypot(p.x - line[0].x, p.y - line[0].y);
  for (std::size_t i = 1; i < line.size(); ++i)
    best = std::min(best, distance_to_segment(p, line[i - 1], line[i]));
  return best;
}

// A damped spiral in pixels, 20 000 points: the kind of curve a phase portrait draws.
std::vector<Point> dense_spiral() {
  std::vector<Point> points;
  for (int i = 0; i < 20000; ++i) {
    const double t = i * 1e-3;
    const double r = 300.0 * std::exp(-0.1 * t);
    points.push_back({600.0 + r * std::cos(3.0 * t), 400.0 + r * std::sin(3.0 * t)});
  }
  return points;
}

TEST(Thin, KeepsEveryPointWithinTheTolerance) {
  const auto points = dense_spiral();
  for (double tolerance : {0.1, 0.25, 1.0}) {
    const auto thinned = thin_polyline(points, tolerance);
    double worst = 0.0;
    for (const Point& p : points) worst = std::max(worst, distance_to_polyline(p, thinned));
    EXPECT_LE(worst, tolerance + 1e-9) << "tolerance " << tolerance;
  }
}

// A long φ(t) seen from afar: a zigzag of many turns per pixel over several of the thinning's
// spans (render/thin.cpp), whose ends must keep the tolerance like any point.
TEST(Thin, KeepsAZigzagWithinTheToleranceAcrossSpans) {
  std::vector<Point> points;
  for (int i = 0; i < 6000; ++i) points.push_back({0.01 * i, i % 2 ? 10.0 : 90.0 + 0.1 * (i % 7)});
  const auto thinned = thin_polyline(points, 0.25);
  double worst = 0.0;
  for (const Point& p : points) worst = std::max(worst, distance_to_polyline(p, thinned));
  EXPECT_LE(worst, 0.25 + 1e-9);
  EXPECT_EQ(thinned.front().x, points.front().x);
  EXPECT_EQ(thinned.back().x, points.back().x);
}

TEST(Thin, ReducesADenseCurve) {
  const auto points = dense_spiral();
  const auto thinned = thin_polyline(points, 0.25);
  EXPECT_LT(thinned.size(), points.size() / 10);
  EXPECT_GT(thinned.size(), 50u);  // a spiral is not a straight line
}

TEST(Thin, KeepsTheEnds) {
  const auto points = dense_spiral();
  const auto thinned = thin_polyline(points, 0.25);
  EXPECT_EQ(thinned.front().x, points.front().x);
  EXPECT_EQ(thinned.back().y, points.back().y);
}

TEST(Thin, StraightLineBecomesTwoPoints) {
  std::vector<Point> line;
  for (int i = 0; i <= 1000; ++i) line.push_back({0.5 * i, 0.25 * i});
  const auto thinned = thin_polyline(line, 0.25);
  ASSERT_EQ(thinned.size(), 2u);
  EXPECT_EQ(thinned[1].x, 500.0);
}

TEST(Thin, ShortInputsPassThrough) {
  EXPECT_TRUE(thin_polyline({}, 0.25).empty());
  const std::vector<Point> one{{1.0, 2.0}};
  EXPECT_EQ(thin_polyline(one, 0.25).size(), 1u);
  const std::vector<Point> two{{1.0, 2.0}, {1.0, 2.0}};
  EXPECT_EQ(thin_polyline(two, 0.25).size(), 2u);
}

}  // namespace
}  // namespace vibro::render
