// The 3-D panel's geometry and arithmetic, checked without GL.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/gl/branch_palette.h"
#include "render/gl/cylinder_camera.h"
#include "render/gl/cylinder_guides.h"
#include "render/gl/cylinder_layout.h"
#include "render/gl/downsample.h"
#include "render/gl/trajectory_tube.h"
#include "render/gl/view_math.h"
#include "tests/render3d/synthetic_trajectory.h"

namespace vibro::gl {
namespace {

bool same(Rgb8 a, Rgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

TEST(BranchPalette, CyclesAndAcceptsNegativeIndices) {
  const int n = static_cast<int>(kBranchPalette.size());
  EXPECT_TRUE(same(branch_colour(0), kBranchPalette[0]));
  EXPECT_TRUE(same(branch_colour(n + 2), kBranchPalette[2]));
  EXPECT_TRUE(same(branch_colour(-1), kBranchPalette[n - 1]));
  EXPECT_FALSE(same(branch_colour(0), branch_colour(1)));
}

TEST(HeightScale, CoversTheDataWithAMargin) {
  const CylinderScene scene = testing::damped_spiral_scene();
  const HeightScale scale = height_scale(scene);
  for (const CylinderBranch& branch : scene.branches) {
    for (const PhasePoint& p : branch.points) {
      EXPECT_GT(scale.z(p.dphi), -kHalfHeight);
      EXPECT_LT(scale.z(p.dphi), kHalfHeight);
    }
  }
}

TEST(HeightScale, UsesTheScenesRangeWhenGiven) {
  CylinderScene scene = testing::damped_spiral_scene();
  scene.dphi_range = DphiRange{-10.0, 30.0};
  const HeightScale scale = height_scale(scene);
  EXPECT_DOUBLE_EQ(scale.z(-10.0), -kHalfHeight);
  EXPECT_DOUBLE_EQ(scale.z(30.0), kHalfHeight);
}

TEST(HeightScale, HandlesEmptyAndFlatTrajectories) {
  const HeightScale empty = height_scale(CylinderScene{});
  EXPECT_LT(empty.lo, 0.0);
  EXPECT_GT(empty.hi, 0.0);
  CylinderScene flat;
  flat.branches.push_back({0, {{0.0, 3.0}, {1.0, 3.0}}});
  const HeightScale scale = height_scale(flat);
  EXPECT_DOUBLE_EQ(scale.z(3.0), 0.0);
}

TEST(TrajectoryTube, HugsTheCylinderWithUnitNormals) {
  const CylinderScene scene = testing::damped_spiral_scene();
  const double radius = 0.02;
  const Mesh tube = trajectory_tube(scene, height_scale(scene), radius);
  ASSERT_FALSE(tube.indices.empty());
  EXPECT_EQ(tube.indices.size() % 3, 0u);
  for (std::uint32_t i : tube.indices) ASSERT_LT(i, tube.vertices.size());
  for (const Vertex& v : tube.vertices) {
    const double r = std::hypot(v.position[0], v.position[1]);
    EXPECT_NEAR(r, 1.0, radius * 1.01);
    EXPECT_LE(std::abs(v.position[2]), kHalfHeight + radius);
    EXPECT_NEAR(std::hypot(v.normal[0], v.normal[1], v.normal[2]), 1.0, 1e-5);
  }
}

TEST(TrajectoryTube, FollowsWrappedAngleTheShortWayRound) {
  CylinderScene scene;
  // φ wrapped into (-π, π]: the step from just below π to just above -π is a small one.
  scene.branches.push_back({0, {{3.0, 0.0}, {3.1, 0.0}, {-3.1, 0.0}, {-3.0, 0.0}}});
  const Mesh tube = trajectory_tube(scene, height_scale(scene), 0.01);
  for (const Vertex& v : tube.vertices) EXPECT_LT(v.position[0], -0.95);
}

TEST(TrajectoryTube, NonFinitePointsSplitABranchAndStillPointsDrawNothing) {
  CylinderScene scene;
  scene.branches.push_back({0, {{0.0, 0.0}, {0.5, 1.0}}});
  const std::size_t one_piece = trajectory_tube(scene, {}, 0.01).indices.size();
  scene.branches[0].points.push_back({NAN, 0.0});
  scene.branches[0].points.push_back({2.0, 0.0});
  scene.branches[0].points.push_back({2.5, 1.0});
  EXPECT_EQ(trajectory_tube(scene, {}, 0.01).indices.size(), 2 * one_piece);
  CylinderScene still;
  still.branches.push_back({0, {{1.0, 1.0}, {1.0, 1.0}}});
  EXPECT_TRUE(trajectory_tube(still, {}, 0.01).vertices.empty());
}

TEST(CylinderGuides, PutsALimiterLineAtEachFiniteAngle) {
  const LineSet lines = limiter_lines({0.0, std::numbers::pi / 2, NAN});
  ASSERT_EQ(lines.vertices.size(), 4u);
  EXPECT_FLOAT_EQ(lines.vertices[0].position[0], 1.0f);
  EXPECT_FLOAT_EQ(lines.vertices[0].position[2], static_cast<float>(-kHalfHeight));
  EXPECT_FLOAT_EQ(lines.vertices[1].position[2], static_cast<float>(kHalfHeight));
  EXPECT_NEAR(lines.vertices[2].position[1], 1.0f, 1e-6);
}

TEST(CylinderGuides, DrawsTheZeroRingOnlyWhenZeroIsInRange) {
  auto count = [](const HeightScale& s) {
    std::size_t n = 0;
    for (const LineSet& set : guide_lines(s)) n += set.vertices.size();
    return n;
  };
  EXPECT_GT(count({-1.0, 1.0}), count({1.0, 2.0}));
}

// Where a projection puts a point, in pixels of a width × height viewport.
std::array<double, 2> to_pixels(const Mat4& m, Vec3 p, int width, int height) {
  const Vec3 ndc = transform_point(m, p);
  return {(ndc.x + 1.0) * 0.5 * width, (ndc.y + 1.0) * 0.5 * height};
}

TEST(ViewMath, CroppedTileSeesThePointWhereTheFullViewDoes) {
  const Mat4 full =
      frustum(-0.8, 0.6, -0.3, 0.4, 0.5, 10.0) * look_at({3.0, 1.0, 1.0}, {}, {0.0, 0.0, 1.0});
  const Vec3 p{0.3, -0.2, 0.4};
  const auto whole = to_pixels(full, p, 800, 400);
  const Mat4 tile = crop_to_tile(full, 800, 400, 300, 100, 500, 350);
  const auto local = to_pixels(tile, p, 200, 250);
  EXPECT_NEAR(local[0] + 300, whole[0], 1e-9);
  EXPECT_NEAR(local[1] + 100, whole[1], 1e-9);
}

TEST(ViewMath, LookAtPutsTheTargetStraightAhead) {
  const Mat4 view = look_at({0.0, -4.0, 0.0}, {}, {0.0, 0.0, 1.0});
  const Vec3 target = transform_point(view, {});
  EXPECT_NEAR(target.x, 0.0, 1e-12);
  EXPECT_NEAR(target.y, 0.0, 1e-12);
  EXPECT_NEAR(target.z, -4.0, 1e-12);
  const Vec3 above = transform_point(view, {0.0, 0.0, 1.0});
  EXPECT_NEAR(above.y, 1.0, 1e-12);
}

// The extent of the cylinder's rims in normalised device coordinates.
struct Extent {
  double left = 1e9, right = -1e9, bottom = 1e9, top = -1e9;
};
Extent rim_extent(const ViewSetup& setup) {
  Extent e;
  for (int i = 0; i < 360; ++i) {
    for (double z : {-kHalfHeight, kHalfHeight}) {
      const Vec3 p = transform_point(setup.projection * setup.view,
                                     on_cylinder(i * std::numbers::pi / 180.0, z));
      e.left = std::min(e.left, p.x);
      e.right = std::max(e.right, p.x);
      e.bottom = std::min(e.bottom, p.y);
      e.top = std::max(e.top, p.y);
    }
  }
  return e;
}

TEST(CylinderCamera, FramesTheCylinderWholeAndLarge) {
  for (const Camera& camera :
       {Camera{}, Camera{-120.0, 70.0, 2.0}, Camera{10.0, -30.0, 12.0}, Camera{0.0, 0.0, 0.1}}) {
    for (auto [w, h] : {std::pair{400, 400}, {800, 300}, {300, 800}}) {
      const Extent e = rim_extent(cylinder_camera(camera, w, h));
      EXPECT_GT(e.left, -1.0);
      EXPECT_LT(e.right, 1.0);
      EXPECT_GT(e.bottom, -1.0);
      EXPECT_LT(e.top, 1.0);
      // It fills the panel one way or the other.
      EXPECT_GT(std::max(e.right - e.left, e.top - e.bottom), 1.4);
    }
  }
}

TEST(CylinderCamera, PutsTheRequestedAzimuthInFront) {
  // From azimuth 90° the camera is on the +y side: the point at φ = 90° is nearest.
  const ViewSetup setup = cylinder_camera(Camera{90.0, 0.0, 4.0}, 100, 100);
  const double near = transform_point(setup.view, {0.0, 1.0, 0.0}).z;
  const double far = transform_point(setup.view, {0.0, -1.0, 0.0}).z;
  EXPECT_GT(near, far);  // eye space looks down -z: nearer is larger
}

TEST(Downsample, AveragesBlocksAndFlipsRows) {
  // A 4×2 tile, rows bottom to top: bottom row black, top row white, in 2×2 blocks.
  std::vector<std::uint8_t> tile(4 * 2 * 4, 0);
  for (int x = 0; x < 4; ++x) {
    for (int c = 0; c < 3; ++c) tile[(4 + x) * 4 + c] = x < 2 ? 255 : 100;
  }
  Image out{3, 1, std::vector<std::uint8_t>(3 * 1 * 4, 7)};
  downsample_tile(tile, 4, 2, 2, 1, 0, &out);
  EXPECT_EQ(out.rgba[0], 7);    // left of the tile: untouched
  EXPECT_EQ(out.rgba[4], 128);  // (255 + 255 + 0 + 0) / 4, rounded
  EXPECT_EQ(out.rgba[8], 50);   // (100 + 100 + 0 + 0) / 4
  EXPECT_EQ(out.rgba[7], 255);  // opaque
}

}  // namespace
}  // namespace vibro::gl
