#include "render/png.h"

#include <libdeflate.h>

#include <cmath>
#include <string_view>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "render/image_deflate.h"

namespace vibro::render {
namespace {

struct SurfacePixels {
  const std::uint32_t* words;
  std::size_t stride;  // in words
  int width;

  const std::uint32_t* row(int y) const { return words + static_cast<std::size_t>(y) * stride; }
};

// 0x??RRGGBB words to R, G, B bytes: four pixels per SSSE3 byte shuffle where the CPU has it
// (every x86-64 CPU of the last fifteen years; checked at run time), one at a time otherwise.
#if defined(__x86_64__)
__attribute__((target("ssse3"))) int rgb_quads_ssse3(const std::uint32_t* in, int width,
                                                     std::uint8_t* out) {
  const __m128i order = _mm_setr_epi8(2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1);
  int x = 0;
  // Each store writes 16 bytes for 12: the 4 bytes past a quad must still lie in the row
  // (3·x + 16 <= 3·width), the rest of the row goes the scalar way.
  for (; 3 * x + 16 <= 3 * width; x += 4, out += 12) {
    const __m128i p = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + x));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_shuffle_epi8(p, order));
  }
  return x;
}
bool have_ssse3() {
  static const bool have = (__builtin_cpu_init(), __builtin_cpu_supports("ssse3"));
  return have;
}
#endif

void rgb_row(const void* source, int y, std::uint8_t* out) {
  const auto& s = *static_cast<const SurfacePixels*>(source);
  const std::uint32_t* in = s.row(y);
  int x = 0;
#if defined(__x86_64__)
  if (have_ssse3()) {
    x = rgb_quads_ssse3(in, s.width, out);
    out += 3 * static_cast<std::size_t>(x);
  }
#endif
  for (; x < s.width; ++x, out += 3) {
    const std::uint32_t word = in[x];
    out[0] = static_cast<std::uint8_t>(word >> 16);
    out[1] = static_cast<std::uint8_t>(word >> 8);
    out[2] = static_cast<std::uint8_t>(word);
  }
}

void unpremultiplied_row(const void* source, int y, std::uint8_t* out) {
  const auto& s = *static_cast<const SurfacePixels*>(source);
  const std::uint32_t* in = s.row(y);
  for (int x = 0; x < s.width; ++x, out += 4) {
    const std::uint32_t word = in[x];
    const unsigned a = word >> 24;
    const auto channel = [a](unsigned c) {
      return static_cast<std::uint8_t>(a == 0 ? 0 : (c * 255 + a / 2) / a);
    };
    out[0] = channel((word >> 16) & 0xff);
    out[1] = channel((word >> 8) & 0xff);
    out[2] = channel(word & 0xff);
    out[3] = static_cast<std::uint8_t>(a);
  }
}

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// A chunk: length, type, data, and the CRC-32 of type and data.
void put_chunk(std::vector<std::uint8_t>& out, std::string_view type,
               const std::vector<std::uint8_t>& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type.begin(), type.end());
  out.insert(out.end(), data.begin(), data.end());
  put_u32(out, libdeflate_crc32(0, out.data() + start, out.size() - start));
}

}  // namespace

std::vector<std::uint8_t> encode_png_argb32(const std::uint8_t* data, int width, int height,
                                            int stride, bool opaque, double dpi) {
  if (!data || width <= 0 || height <= 0 || stride < 4 * width || stride % 4 != 0) return {};
  // cairo writes its pixels as 32-bit words, 4-byte aligned (its strides are multiples of 4).
  const SurfacePixels pixels{reinterpret_cast<const std::uint32_t*>(data),
                             static_cast<std::size_t>(stride) / 4, width};
  ImageRows rows;
  rows.width = width;
  rows.height = height;
  rows.channels = opaque ? 3 : 4;
  rows.keys = pixels.words;
  rows.key_stride = pixels.stride;
  rows.key_mask = opaque ? 0x00FFFFFFu : 0xFFFFFFFFu;
  rows.row = opaque ? rgb_row : unpremultiplied_row;
  rows.source = &pixels;

  std::vector<std::uint8_t> header;
  put_u32(header, static_cast<std::uint32_t>(width));
  put_u32(header, static_cast<std::uint32_t>(height));
  // 8 bits per channel, RGB (2) or RGBA (6), DEFLATE, adaptive filters, no interlacing.
  header.insert(header.end(), {8, static_cast<std::uint8_t>(opaque ? 2 : 6), 0, 0, 0});

  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  put_chunk(out, "IHDR", header);
  if (dpi > 0.0) {
    // Pixels per metre along x and y, then the unit (1: the metre).
    const auto per_metre = static_cast<std::uint32_t>(std::lround(dpi / 0.0254));
    std::vector<std::uint8_t> physical;
    put_u32(physical, per_metre);
    put_u32(physical, per_metre);
    physical.push_back(1);
    put_chunk(out, "pHYs", physical);
  }
  put_chunk(out, "IDAT", zlib_image_rows(rows));
  put_chunk(out, "IEND", {});
  return out;
}

}  // namespace vibro::render
