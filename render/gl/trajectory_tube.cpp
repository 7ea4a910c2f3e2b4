#include "render/gl/trajectory_tube.h"

#include <algorithm>
#include <numbers>
#include <span>

#include "render/gl/branch_palette.h"

namespace vibro::gl {
namespace {

constexpr int kSides = 8;
// Largest φ step of a chord: longer chords would cut visibly inside the cylinder.
constexpr double kMaxPhiStep = 0.04;
// Rings are kept where the path has turned this much (rad) since the last ring, or has
// run this far (scene units): dense samples on a straight stretch add nothing to see.
constexpr double kMaxTurn = 0.08;
constexpr double kMaxRun = 0.15;

// The path of one unbroken run of samples on the cylinder, with long φ steps subdivided.
// φ steps are taken the short way round, so wrapped and unwrapped φ draw alike.
std::vector<Vec3> dense_path(std::span<const PhasePoint> run, const HeightScale& scale) {
  std::vector<Vec3> path;
  if (run.empty()) return path;
  path.push_back(on_cylinder(run[0].phi, scale.z(run[0].dphi)));
  for (std::size_t i = 1; i < run.size(); ++i) {
    const PhasePoint& a = run[i - 1];
    const PhasePoint& b = run[i];
    const double step = std::remainder(b.phi - a.phi, 2.0 * std::numbers::pi);
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(step) / kMaxPhiStep)));
    for (int k = 1; k <= pieces; ++k) {
      const double u = static_cast<double>(k) / pieces;
      path.push_back(on_cylinder(a.phi + u * step, scale.z(a.dphi + u * (b.dphi - a.dphi))));
    }
  }
  return path;
}

double angle_between(Vec3 a, Vec3 b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// The points of `path` where rings go: both ends, and enough between to follow its bends.
std::vector<Vec3> ring_centres(const std::vector<Vec3>& path) {
  constexpr double kSamePoint = 1e-9;
  std::vector<Vec3> kept;
  if (path.empty()) return kept;
  kept.push_back(path.front());
  double turn = 0.0;
  double run = 0.0;
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Vec3 in = path[i] - path[i - 1];
    const Vec3 out = path[i + 1] - path[i];
    if (norm(in) < kSamePoint || norm(out) < kSamePoint) continue;
    turn += angle_between(in, out);
    run += norm(in);
    if (turn > kMaxTurn || run + norm(out) > kMaxRun) {
      if (norm(path[i] - kept.back()) > kSamePoint) kept.push_back(path[i]);
      turn = 0.0;
      run = 0.0;
    }
  }
  if (norm(path.back() - kept.back()) > kSamePoint) kept.push_back(path.back());
  return kept;
}

Vec3 any_perpendicular(Vec3 t) {
  const Vec3 axis = std::abs(t.z) < 0.9 ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0};
  return normalized(cross(t, axis));
}

// A flat disc closing the tube at `centre`, facing `outward`, fanned counter-clockwise as
// seen from that side.
void add_cap(Mesh& mesh, Vec3 centre, Vec3 outward, Vec3 n, Vec3 b, double radius, Rgb8 colour) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(make_vertex(centre, outward, colour));
  for (int s = 0; s < kSides; ++s) {
    const double a = 2.0 * std::numbers::pi * s / kSides;
    const Vec3 r = std::cos(a) * n + std::sin(a) * b;
    mesh.vertices.push_back(make_vertex(centre + radius * r, outward, colour));
  }
  // The ring runs counter-clockwise about n × b; flip the fan when the cap faces the other way.
  const bool flip = dot(cross(n, b), outward) < 0.0;
  for (int s = 0; s < kSides; ++s) {
    const std::uint32_t p = first + 1 + s;
    const std::uint32_t q = first + 1 + (s + 1) % kSides;
    mesh.indices.insert(mesh.indices.end(), {first, flip ? q : p, flip ? p : q});
  }
}

void add_tube(Mesh& mesh, const std::vector<Vec3>& centres, double radius, Rgb8 colour) {
  const std::size_t m = centres.size();
  if (m < 2) return;
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  Vec3 n;
  Vec3 b;
  Vec3 t0;
  Vec3 n0;
  Vec3 b0;
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 t = normalized(centres[std::min(i + 1, m - 1)] - centres[i == 0 ? 0 : i - 1]);
    // Parallel transport: the frame turns only as much as the path does, so the tube's
    // facets do not twist.
    n = i == 0 ? any_perpendicular(t) : normalized(n - dot(n, t) * t);
    if (norm(n) < 0.5) n = any_perpendicular(t);
    b = cross(t, n);
    if (i == 0) {
      t0 = t;
      n0 = n;
      b0 = b;
    }
    for (int s = 0; s < kSides; ++s) {
      const double a = 2.0 * std::numbers::pi * s / kSides;
      const Vec3 r = std::cos(a) * n + std::sin(a) * b;
      mesh.vertices.push_back(make_vertex(centres[i] + radius * r, r, colour));
    }
  }
  for (std::size_t i = 0; i + 1 < m; ++i) {
    for (int s = 0; s < kSides; ++s) {
      const auto a = static_cast<std::uint32_t>(first + i * kSides + s);
      const auto c = static_cast<std::uint32_t>(first + i * kSides + (s + 1) % kSides);
      mesh.indices.insert(mesh.indices.end(), {a, c, a + kSides, c, c + kSides, a + kSides});
    }
  }
  const Vec3 t_end = normalized(centres[m - 1] - centres[m - 2]);
  add_cap(mesh, centres[0], -1.0 * t0, n0, b0, radius, colour);
  add_cap(mesh, centres[m - 1], t_end, n, b, radius, colour);
}

}  // namespace

Mesh trajectory_tube(const CylinderScene& scene, const HeightScale& scale, double radius) {
  Mesh mesh;
  for (const CylinderBranch& branch : scene.branches) {
    const Rgb8 colour = branch_colour(branch.index);
    const std::span<const PhasePoint> points(branch.points);
    std::size_t start = 0;
    for (std::size_t i = 0; i <= points.size(); ++i) {
      const bool finite =
          i < points.size() && std::isfinite(points[i].phi) && std::isfinite(points[i].dphi);
      if (finite) continue;
      add_tube(mesh, ring_centres(dense_path(points.subspan(start, i - start), scale)), radius,
               colour);
      start = i + 1;
    }
  }
  return mesh;
}

}  // namespace vibro::gl
