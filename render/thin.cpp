#include "render/thin.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vibro::render {
namespace {

// Keeps a point only once it is farther than `radius` from the last kept one (and the last).
std::vector<Point> radial_filter(std::span<const Point> points, double radius) {
  std::vector<Point> kept;
  kept.reserve(points.size());
  const double r2 = radius * radius;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point p = points[i];
    if (!kept.empty() && i + 1 < points.size()) {
      const double dx = p.x - kept.back().x, dy = p.y - kept.back().y;
      if (dx * dx + dy * dy <= r2) continue;
    }
    kept.push_back(p);
  }
  return kept;
}

// Pixel coordinates are bounded (render/polyline.h clamps them near the plot), so squares do not
// overflow and std::hypot's care, several times the cost, buys nothing.
double squared_distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
  const double ex = p.x - (a.x + t * dx), ey = p.y - (a.y + t * dy);
  return ex * ex + ey * ey;
}

// Ramer–Douglas–Peucker with an explicit stack (no recursion depth limit on long branches), over
// spans of at most kSpan points whose ends are kept. A span's work grows with the square of its
// length where the curve turns often (a zigzag splits near one end at every step): a φ(t) of
// 200 000 samples took seconds in one span, and the spans' ends cost a point per kSpan.
constexpr std::size_t kSpan = 2048;

std::vector<Point> douglas_peucker(const std::vector<Point>& points, double tolerance) {
  const std::size_t n = points.size();
  if (n < 3) return points;
  std::vector<bool> keep(n, false);
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  for (std::size_t first = 0; first + 1 < n; first += kSpan) {
    const std::size_t last = std::min(n - 1, first + kSpan);
    keep[first] = keep[last] = true;
    stack.push_back({first, last});
  }
  while (!stack.empty()) {
    const auto [first, last] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t worst_index = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double d = squared_distance_to_segment(points[i], points[first], points[last]);
      if (d > worst) worst = d, worst_index = i;
    }
    if (worst > tolerance * tolerance) {
      keep[worst_index] = true;
      stack.push_back({first, worst_index});
      stack.push_back({worst_index, last});
    }
  }
  std::vector<Point> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) kept.push_back(points[i]);
  return kept;
}

}  // namespace

double distance_to_segment(Point p, Point a, Point b) {
  return std::sqrt(squared_distance_to_segment(p, a, b));
}

std::vector<Point> thin_polyline(std::span<const Point> points, double tolerance_px) {
  return douglas_peucker(radial_filter(points, 0.5 * tolerance_px), 0.5 * tolerance_px);
}

}  // namespace vibro::render
