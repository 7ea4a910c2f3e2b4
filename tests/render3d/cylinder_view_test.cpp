// Renders through OSMesa. The first test must stay first: it checks that OSMesa is not in
// the process before the first 3-D panel is drawn.
#include "render/gl/cylinder_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "render/gl/branch_palette.h"
#include "render/gl/offscreen_context.h"
#include "tests/render3d/synthetic_trajectory.h"

namespace vibro::gl {
namespace {

using testing::damped_spiral_scene;

bool osmesa_mapped() {
  std::ifstream maps("/proc/self/maps");
  const std::string text((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
  return text.find("OSMesa") != std::string::npos;
}

Image render_ok(const CylinderScene& scene, int width, int height) {
  std::string error;
  Image image = render_cylinder_view(scene, width, height, &error);
  EXPECT_EQ(error, "");
  return image;
}

const std::uint8_t* pixel(const Image& image, int x, int y) {
  return image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
}

int count_pixels(const Image& image, auto predicate) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) n += predicate(pixel(image, x, y)) ? 1 : 0;
  }
  return n;
}

bool non_white(const std::uint8_t* p) { return p[0] < 245 || p[1] < 245 || p[2] < 245; }
bool near_black(const std::uint8_t* p) { return p[0] < 70 && p[1] < 70 && p[2] < 70; }

// Shading scales a colour and highlights add white, so compare hue direction: the angle
// between the pixel's and the palette colour's RGB vectors, on clearly coloured pixels.
bool has_hue_of(const std::uint8_t* p, Rgb8 c) {
  const double a[3] = {double(p[0]), double(p[1]), double(p[2])};
  const double b[3] = {double(c.r), double(c.g), double(c.b)};
  const double spread = std::max({a[0], a[1], a[2]}) - std::min({a[0], a[1], a[2]});
  if (spread < 60.0) return false;
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  return dot / (na * nb) > std::cos(3.0 * std::numbers::pi / 180.0);
}

int differing_pixels(const Image& a, const Image& b) {
  int n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    const int d = std::abs(a.rgba[i] - b.rgba[i]) + std::abs(a.rgba[i + 1] - b.rgba[i + 1]) +
                  std::abs(a.rgba[i + 2] - b.rgba[i + 2]);
    n += d > 30 ? 1 : 0;
  }
  return n;
}

TEST(CylinderView, LoadsOsmesaOnlyWhenFirstDrawn) {
  EXPECT_FALSE(osmesa_loaded());
  EXPECT_FALSE(osmesa_mapped());
  render_ok(damped_spiral_scene(), 64, 64);
  EXPECT_TRUE(osmesa_loaded());
  EXPECT_TRUE(osmesa_mapped());
}

TEST(CylinderView, HasTheRequestedSizeAndIsOpaque) {
  const Image image = render_ok(damped_spiral_scene(), 320, 200);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 200);
  ASSERT_EQ(image.rgba.size(), 320u * 200u * 4u);
  EXPECT_EQ(count_pixels(image, [](const std::uint8_t* p) { return p[3] != 255; }), 0);
}

TEST(CylinderView, DrawsEveryBranchInItsColour) {
  const Image image = render_ok(damped_spiral_scene(5), 400, 400);
  EXPECT_GT(count_pixels(image, non_white), 400 * 400 / 10);
  for (int branch = 0; branch < 5; ++branch) {
    const Rgb8 colour = branch_colour(branch);
    EXPECT_GT(count_pixels(image, [&](const std::uint8_t* p) { return has_hue_of(p, colour); }), 50)
        << "branch " << branch;
  }
}

TEST(CylinderView, ChangesWithTheCamera) {
  CylinderScene scene = damped_spiral_scene();
  const Image before = render_ok(scene, 300, 300);
  scene.camera.azimuth_deg += 60.0;
  const Image turned = render_ok(scene, 300, 300);
  EXPECT_GT(differing_pixels(before, turned), 300 * 300 / 50);
  scene.camera.elevation_deg = -20.0;
  const Image below = render_ok(scene, 300, 300);
  EXPECT_GT(differing_pixels(turned, below), 300 * 300 / 50);
  scene.camera.distance *= 1.5;
  const Image farther = render_ok(scene, 300, 300);
  EXPECT_GT(differing_pixels(below, farther), 300 * 300 / 50);
}

TEST(CylinderView, DrawsLimiterLines) {
  CylinderScene scene;
  const Image without = render_ok(scene, 300, 300);
  scene.limiter_angles = {0.3, 1.9, 3.5, 5.0};
  const Image with = render_ok(scene, 300, 300);
  // Four lines, each some 200 pixels long: dark ones in front, fogged and veiled behind.
  EXPECT_GT(differing_pixels(with, without), 4 * 150);
  EXPECT_GT(count_pixels(with, near_black), count_pixels(without, near_black) + 150);
}

TEST(CylinderView, EmptyTrajectoryStillDrawsTheCylinder) {
  const Image image = render_ok(CylinderScene{}, 300, 300);
  EXPECT_GT(count_pixels(image, non_white), 300 * 300 / 10);
  for (int branch = 0; branch < 6; ++branch) {
    const Rgb8 colour = branch_colour(branch);
    EXPECT_EQ(count_pixels(image, [&](const std::uint8_t* p) { return has_hue_of(p, colour); }), 0);
  }
}

TEST(CylinderView, RejectsSizesOutOfRange) {
  for (auto [w, h] : {std::pair{0, 100}, {100, 0}, {-5, 10}, {4097, 100}, {100, 4097}}) {
    std::string error;
    const Image image = render_cylinder_view(damped_spiral_scene(), w, h, &error);
    EXPECT_EQ(image.width, 0);
    EXPECT_TRUE(image.rgba.empty());
    EXPECT_NE(error.find("size"), std::string::npos) << error;
  }
}

TEST(CylinderView, RejectsABadCamera) {
  CylinderScene scene = damped_spiral_scene();
  scene.camera.distance = 0.0;
  std::string error;
  EXPECT_TRUE(render_cylinder_view(scene, 100, 100, &error).rgba.empty());
  EXPECT_NE(error.find("distance"), std::string::npos) << error;
  scene.camera = Camera{};
  scene.camera.azimuth_deg = NAN;
  error.clear();
  EXPECT_TRUE(render_cylinder_view(scene, 100, 100, &error).rgba.empty());
  EXPECT_NE(error.find("angle"), std::string::npos) << error;
}

TEST(CylinderView, Renders1024Square) {
  const Image image = render_ok(damped_spiral_scene(8, 2000), 1024, 1024);
  EXPECT_EQ(image.width, 1024);
  EXPECT_GT(count_pixels(image, non_white), 1024 * 1024 / 10);
}

TEST(CylinderView, TilesAWidePanelWithoutSeams) {
  // Wider than one tile: the cylinder must come out centred and whole.
  const Image image = render_ok(CylinderScene{}, 2400, 400);
  int left = image.width;
  int right = -1;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (non_white(pixel(image, x, y))) {
        left = std::min(left, x);
        right = std::max(right, x);
      }
    }
  }
  EXPECT_NEAR((left + right) / 2.0, image.width / 2.0, 4.0);
}

TEST(CylinderView, SerialisesConcurrentCalls) {
  const CylinderScene scene = damped_spiral_scene();
  const Image reference = render_ok(scene, 200, 150);
  std::vector<Image> images(4);
  std::vector<std::thread> threads;
  for (Image& image : images) {
    threads.emplace_back(
        [&scene, &image] { image = render_cylinder_view(scene, 200, 150, nullptr); });
  }
  for (std::thread& t : threads) t.join();
  for (const Image& image : images) EXPECT_EQ(image.rgba, reference.rgba);
}

}  // namespace
}  // namespace vibro::gl
