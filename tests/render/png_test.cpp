#include "render/png.h"

#include <gtest/gtest.h>

#include <cstring>

#include "png_decode.h"
#include "render/image_surface.h"

namespace vibro::render {
namespace {

Image gradient(int w, int h) {
  Image image{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 5);
      p[2] = 200;
      p[3] = 255;
    }
  return image;
}

TEST(Png, EncodesAnImageThatDecodesToTheSamePixels) {
  const Image image = gradient(37, 23);
  const auto bytes = encode_png(image);
  ASSERT_FALSE(bytes.empty());
  const auto decoded = testing::decode_png(bytes);
  ASSERT_EQ(decoded.width, 37);
  ASSERT_EQ(decoded.height, 23);
  EXPECT_EQ(decoded.at(10, 20), 0xFF000000u | (70u << 16) | (100u << 8) | 200u);
}

TEST(Png, EncodesAnOpaqueSurfaceAsRgb) {
  std::vector<std::uint32_t> words(8 * 4, 0xFF102030u);
  words[9] = 0xFFFF0000u;
  const auto bytes =
      encode_png_argb32(reinterpret_cast<const std::uint8_t*>(words.data()), 8, 4, 32, true);
  const auto decoded = testing::decode_png(bytes);
  ASSERT_EQ(decoded.width, 8);
  EXPECT_EQ(decoded.at(1, 1), 0xFFFF0000u);
  EXPECT_EQ(decoded.at(0, 0), 0xFF102030u);
  EXPECT_EQ(bytes[25], 2);  // IHDR colour type: RGB
}

TEST(Png, DividesOutPremultipliedAlpha) {
  std::vector<std::uint32_t> words(4, 0x80400000u);  // half-transparent, premultiplied red 0x40
  const auto bytes =
      encode_png_argb32(reinterpret_cast<const std::uint8_t*>(words.data()), 2, 2, 8, false);
  EXPECT_EQ(bytes[25], 6);  // IHDR colour type: RGBA
  const auto decoded = testing::decode_png(bytes);
  ASSERT_EQ(decoded.width, 2);
  // cairo premultiplies again on decoding: the round trip gives back the input within rounding.
  const std::uint32_t px = decoded.at(1, 1);
  EXPECT_EQ(px >> 24, 0x80u);
  EXPECT_NEAR(static_cast<int>((px >> 16) & 0xff), 0x40, 1);
}

TEST(Png, RefusesBadInput) {
  EXPECT_TRUE(encode_png(Image{}).empty());
  EXPECT_TRUE(encode_png(Image{4, 4, std::vector<std::uint8_t>(10)}).empty());
  EXPECT_TRUE(encode_png_argb32(nullptr, 4, 4, 16, true).empty());
}

TEST(ImageSurface, PremultipliesStraightAlpha) {
  Image image{1, 1, {200, 100, 0, 128}};
  const SurfacePtr s = surface_from_image(image);
  ASSERT_TRUE(s);
  std::uint32_t word;
  std::memcpy(&word, cairo_image_surface_get_data(s.get()), 4);
  EXPECT_EQ(word >> 24, 128u);
  EXPECT_EQ((word >> 16) & 0xff, 100u);  // 200 × 128 / 255
  EXPECT_FALSE(surface_from_image(Image{}));
}

}  // namespace
}  // namespace vibro::render
