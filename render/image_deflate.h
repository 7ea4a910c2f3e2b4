// The zlib stream (RFC 1950/1951) of an image's PNG rows, made for figures: most of a figure
// repeats the pixel to its left (flat fills, horizontal lines) or the one above it (vertical
// lines, blank rows). Each pixel is matched against those two, and only the rest is sent as
// literals, each block under Huffman codes of its own statistics. General-purpose deflaters
// search every byte for matches: on the paper figure (1200×800) this is 4× faster than zlib's
// fastest level and 18× faster than cairo's own PNG writer, for 12 % more bytes than zlib's
// fastest level (bench/png_bench.cpp, docs/PERFORMANCE.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vibro::render {

// An image as PNG rows (filter type 0): `width` pixels of `channels` bytes (3: RGB, 4: RGBA).
// `row(y, out)` writes row y's width × channels bytes to `out`; `keys` holds one 32-bit word per
// pixel (row y at keys + y · key_stride) such that equal words give equal bytes. Different words
// may still give equal bytes; they are merely not matched.
struct ImageRows {
  int width = 0;
  int height = 0;
  int channels = 3;
  const std::uint32_t* keys = nullptr;
  std::size_t key_stride = 0;            // in words
  std::uint32_t key_mask = 0xFFFFFFFFu;  // the bits of a key that matter
  void (*row)(const void* source, int y, std::uint8_t* out) = nullptr;
  const void* source = nullptr;
};

// The zlib stream of the rows, each preceded by its filter byte 0.
std::vector<std::uint8_t> zlib_image_rows(const ImageRows& image);

}  // namespace vibro::render
