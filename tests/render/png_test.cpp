// The PNG encoder against two independent decoders: zlib's inflate (every byte of the rows,
// the Adler-32 and each chunk's CRC) and cairo's PNG reader (libpng).
#include "render/png.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <random>
#include <string>

#include "png_decode.h"
#include "render/image_surface.h"

namespace vibro::render {
namespace {

// An opaque surface's words, `width` × `height`, stride = width words.
struct Words {
  int width;
  int height;
  std::vector<std::uint32_t> words;

  std::uint32_t& at(int x, int y) { return words[static_cast<std::size_t>(y) * width + x]; }
  const std::uint8_t* data() const { return reinterpret_cast<const std::uint8_t*>(words.data()); }
  std::vector<std::uint8_t> png(bool opaque = true) const {
    return encode_png_argb32(data(), width, height, 4 * width, opaque);
  }
};

std::uint32_t read_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
         (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

// The IDAT stream inflated by zlib (which checks its Adler-32), every chunk's CRC checked.
std::vector<std::uint8_t> inflated_rows(const std::vector<std::uint8_t>& png, std::size_t size) {
  std::vector<std::uint8_t> idat;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = read_u32(png, at);
    const std::string type(png.begin() + static_cast<long>(at) + 4,
                           png.begin() + static_cast<long>(at) + 8);
    const uLong crc = crc32(0, png.data() + at + 4, length + 4);
    EXPECT_EQ(crc, read_u32(png, at + 8 + length)) << type;
    if (type == "IDAT")
      idat.insert(idat.end(), png.begin() + static_cast<long>(at) + 8,
                  png.begin() + static_cast<long>(at + 8 + length));
    at += 12 + length;
  }
  std::vector<std::uint8_t> raw(size + 1);
  uLongf raw_size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &raw_size, idat.data(), idat.size()), Z_OK);
  raw.resize(raw_size);
  return raw;
}

// The filter-0 rows an opaque image must inflate to.
std::vector<std::uint8_t> expected_rows(const Words& w) {
  std::vector<std::uint8_t> rows;
  for (int y = 0; y < w.height; ++y) {
    rows.push_back(0);
    for (int x = 0; x < w.width; ++x) {
      const std::uint32_t p = w.words[static_cast<std::size_t>(y) * w.width + x];
      rows.insert(rows.end(), {static_cast<std::uint8_t>(p >> 16),
                               static_cast<std::uint8_t>(p >> 8), static_cast<std::uint8_t>(p)});
    }
  }
  return rows;
}

void expect_round_trip(const Words& w) {
  const auto png = w.png();
  ASSERT_FALSE(png.empty());
  const auto expected = expected_rows(w);
  EXPECT_EQ(inflated_rows(png, expected.size()), expected);
  const auto decoded = testing::decode_png(png);
  ASSERT_EQ(decoded.width, w.width);
  ASSERT_EQ(decoded.height, w.height);
  for (std::size_t i = 0; i < w.words.size(); ++i)
    ASSERT_EQ(decoded.argb[i], w.words[i] | 0xFF000000u) << "pixel " << i;
}

// A figure-like image: white, a grid, horizontal and vertical lines, a curve, noise in a box.
Words figure_like(int width, int height, unsigned seed) {
  Words w{width, height,
          std::vector<std::uint32_t>(static_cast<std::size_t>(width) * height, 0xFFFFFFFFu)};
  std::mt19937 rng(seed);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (x % 50 == 0 || y % 40 == 0) w.at(x, y) = 0xFFE0E0E0u;
      if (y == height / 2) w.at(x, y) = 0xFF000000u;
    }
  for (int x = 0; x < width; ++x) {
    const int y = static_cast<int>(height / 2 + height / 3 * std::sin(x * 0.05));
    w.at(x, y) = 0xFF0072B2u;
    if (y + 1 < height) w.at(x, y + 1) = 0xFF80B9D8u;
  }
  for (int y = height / 4; y < height / 3; ++y)
    for (int x = width / 4; x < width / 3; ++x) w.at(x, y) = rng() | 0xFF000000u;
  return w;
}

TEST(Png, AFigureInflatesToItsRowsAndDecodesToItsPixels) {
  expect_round_trip(figure_like(300, 200, 1));
}

TEST(Png, AFigureCompressesLikeAGeneralDeflater) {
  const Words w = figure_like(1200, 800, 2);
  const auto png = w.png();
  const auto rows = expected_rows(w);
  uLongf size = compressBound(rows.size());
  std::vector<std::uint8_t> zlib_out(size);
  ASSERT_EQ(compress2(zlib_out.data(), &size, rows.data(), rows.size(), 1), Z_OK);
  // Within 30 % of zlib's fastest level (often smaller): the deflater must not trade size away.
  EXPECT_LT(static_cast<double>(png.size()), 1.3 * static_cast<double>(size));
}

TEST(Png, NoiseSpansManyBlocksAndStillRoundTrips) {
  Words w{700, 300, {}};
  std::mt19937 rng(7);
  for (int i = 0; i < 700 * 300; ++i) w.words.push_back(rng() & 0x00FFFFFFu);
  expect_round_trip(w);
}

TEST(Png, EdgeShapesRoundTrip) {
  // Widths 9 and 301 end a row on a whole four-pixel quad plus one pixel: the vector row
  // conversion must not store past the row's end (found by fuzzing under ASan).
  for (const auto& [width, height] :
       {std::pair{1, 1}, {1, 50}, {50, 1}, {2, 3}, {258, 4}, {87, 3}, {86, 5}, {9, 2}, {301, 3}}) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    expect_round_trip(figure_like(width, height, 3));
    // One colour everywhere: runs of every length, split at 258 bytes without short pieces.
    expect_round_trip(
        Words{width, height,
              std::vector<std::uint32_t>(static_cast<std::size_t>(width) * height, 0xFF336699u)});
  }
}

TEST(Png, RowsTooWideToMatchTheRowAboveRoundTrip) {
  // 11000 RGB pixels: the row above lies beyond DEFLATE's 32 KiB window.
  expect_round_trip(figure_like(11000, 6, 4));
}

TEST(Png, IgnoresTheAlphaByteOfAnOpaqueSurface) {
  Words w{8, 4, std::vector<std::uint32_t>(32, 0xFF102030u)};
  w.at(1, 1) = 0xFFFF0000u;
  w.at(2, 1) = 0x00FF0000u;  // the same colour, another alpha byte: RGB24 ignores it
  const auto png = w.png();
  EXPECT_EQ(png[25], 2);  // IHDR colour type: RGB
  const auto decoded = testing::decode_png(png);
  ASSERT_EQ(decoded.width, 8);
  EXPECT_EQ(decoded.at(1, 1), 0xFFFF0000u);
  EXPECT_EQ(decoded.at(2, 1), 0xFFFF0000u);
  EXPECT_EQ(decoded.at(0, 0), 0xFF102030u);
}

TEST(Png, DividesOutPremultipliedAlpha) {
  Words w{2, 2, std::vector<std::uint32_t>(4, 0x80400000u)};  // half-transparent red 0x40
  w.at(0, 0) = 0x00000000u;
  const auto png = w.png(false);
  EXPECT_EQ(png[25], 6);  // IHDR colour type: RGBA
  const auto raw = inflated_rows(png, 2 * (1 + 8));
  ASSERT_EQ(raw.size(), 18u);
  EXPECT_EQ(raw[1 + 3], 0);     // fully transparent: alpha 0
  EXPECT_EQ(raw[1 + 4], 0x80);  // (0x40 · 255 + 64) / 128
  EXPECT_EQ(raw[1 + 4 + 3], 0x80);
  const auto decoded = testing::decode_png(png);
  ASSERT_EQ(decoded.width, 2);
  // cairo premultiplies again on decoding: the round trip gives back the input within rounding.
  const std::uint32_t px = decoded.at(1, 1);
  EXPECT_EQ(px >> 24, 0x80u);
  EXPECT_NEAR(static_cast<int>((px >> 16) & 0xff), 0x40, 1);
}

TEST(Png, RefusesBadInput) {
  const std::vector<std::uint32_t> words(16, 0);
  const auto* data = reinterpret_cast<const std::uint8_t*>(words.data());
  EXPECT_TRUE(encode_png_argb32(nullptr, 4, 4, 16, true).empty());
  EXPECT_TRUE(encode_png_argb32(data, 0, 4, 16, true).empty());
  EXPECT_TRUE(encode_png_argb32(data, 4, 0, 16, true).empty());
  EXPECT_TRUE(encode_png_argb32(data, 4, 4, 12, true).empty());
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
