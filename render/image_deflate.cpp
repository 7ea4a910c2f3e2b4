#include "render/image_deflate.h"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "render/huffman.h"

namespace vibro::render {
namespace {

constexpr int kEndOfBlock = 256;
constexpr int kMaxLength = 258;
constexpr int kMinLength = 3;
constexpr int kMaxDistance = 32768;
constexpr int kLongRun = 32;  // pixels
// A block gets Huffman codes of its own statistics; a few dozen rows of a figure fill one, so
// the codes follow what each band of the figure holds (axes, curves, labels).
constexpr std::size_t kBlockTokens = std::size_t{1} << 16;

// A symbol of a DEFLATE alphabet with the extra bits that follow it.
struct Symbol {
  std::uint16_t code = 0;
  std::uint8_t extra_bits = 0;
  std::uint16_t extra = 0;
};

// RFC 1951, 3.2.5: the first value of each length code 257..285 and of each distance code.
constexpr std::array<int, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                             15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                             67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<int, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                              2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<int, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<int, 30> kDistanceExtra = {0, 0, 0,  0,  1,  1,  2,  2,  3,  3,
                                                4, 4, 5,  5,  6,  6,  7,  7,  8,  8,
                                                9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

template <std::size_t N>
Symbol symbol_of(int value, const std::array<int, N>& base, const std::array<int, N>& extra,
                 int first_code) {
  const auto i = static_cast<std::size_t>(std::upper_bound(base.begin(), base.end(), value) -
                                          base.begin() - 1);
  return {static_cast<std::uint16_t>(first_code + i), static_cast<std::uint8_t>(extra[i]),
          static_cast<std::uint16_t>(value - base[i])};
}

// Every match length's symbol, looked up once per match.
const std::array<Symbol, kMaxLength + 1>& length_symbols() {
  static const auto table = [] {
    std::array<Symbol, kMaxLength + 1> t{};
    for (int length = kMinLength; length <= kMaxLength; ++length)
      t[static_cast<std::size_t>(length)] = symbol_of(length, kLengthBase, kLengthExtra, 257);
    return t;
  }();
  return table;
}
Symbol distance_symbol(int distance) {
  return symbol_of(distance, kDistanceBase, kDistanceExtra, 0);
}

// The tokens of a block: a literal byte, or a match (bit 31) of a length with one of the two
// distances an image uses (bit 9: 0 the pixel to the left, 1 the pixel above).
using Token = std::uint32_t;
constexpr Token kMatch = 0x80000000u;
constexpr Token kAbove = 0x200u;
Token match(int length, bool above) {
  return kMatch | (above ? kAbove : 0u) | static_cast<Token>(length);
}
std::size_t match_length(Token t) { return t & 0x1FFu; }
bool match_above(Token t) { return (t & kAbove) != 0; }

// A block's tokens, with the frequencies of the literal/length symbols and of the two
// distances counted as they come. Literal bytes are counted in four tables by their place in a
// pixel: a grey pixel's three equal bytes would otherwise wait on one counter each in turn.
struct Block {
  static constexpr int kLanes = 4;
  std::vector<Token> tokens;
  std::array<std::array<std::uint32_t, 256>, kLanes> byte_frequency{};
  std::array<std::uint32_t, 286> length_frequency{};  // by symbol (none below 257)
  std::array<std::uint32_t, 2> distance_uses{};       // to the left, above

  void literal(std::uint8_t byte, int lane = 0) {
    tokens.push_back(byte);
    ++byte_frequency[static_cast<std::size_t>(lane)][byte];
  }
  void repeat(int length, bool above) {
    tokens.push_back(match(length, above));
    ++length_frequency[length_symbols()[static_cast<std::size_t>(length)].code];
    ++distance_uses[above ? 1 : 0];
  }
  // Of the literal/length alphabet.
  std::vector<std::uint32_t> literal_frequency() const {
    std::vector<std::uint32_t> f(length_frequency.begin(), length_frequency.end());
    for (const auto& lane : byte_frequency)
      for (std::size_t b = 0; b < lane.size(); ++b) f[b] += lane[b];
    return f;
  }
  void clear() {
    tokens.clear();
    for (auto& lane : byte_frequency) lane.fill(0);
    length_frequency.fill(0);
    distance_uses.fill(0);
  }
};

// Bits least significant first, as DEFLATE packs them, into a buffer sized ahead by the caller
// (`reserve`). Whole bytes go out eight at a time without a branch; `put` takes up to 56 bits
// between two `flush`es.
class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out), size_(out.size()) {}

  // Room for `bytes` more bytes of output.
  void reserve(std::size_t bytes) {
    if (out_.size() < size_ + bytes + 8) out_.resize(std::max(2 * out_.size(), size_ + bytes + 8));
  }

  void put(std::uint64_t bits, int count) {
    buffer_ |= bits << count_;
    count_ += count;
  }

  // Writes out the whole bytes held.
  void flush() {
    std::memcpy(out_.data() + size_, &buffer_, 8);  // little-endian hosts (x86-64, ARM64)
    const int bytes = count_ >> 3;
    size_ += static_cast<std::size_t>(bytes);
    buffer_ >>= 8 * bytes;  // at most 7 bytes: put holds the count under 64
    count_ &= 7;
  }

  // Pads the last byte with zeros and trims the buffer to what was written.
  void finish() {
    reserve(16);
    flush();
    if (count_ > 0) out_[size_++] = static_cast<std::uint8_t>(buffer_);
    buffer_ = 0;
    count_ = 0;
    out_.resize(size_);
  }

 private:
  std::vector<std::uint8_t>& out_;
  std::size_t size_;
  std::uint64_t buffer_ = 0;
  int count_ = 0;
};

// A Huffman code ready to write: each symbol's bit-reversed code, and its length in bits 16+.
struct Code {
  std::vector<std::uint8_t> lengths;
  std::vector<std::uint32_t> entries;

  // The symbol's code followed by its extra bits, as one field of bits: (bits, count).
  std::pair<std::uint64_t, int> field(const Symbol& s) const {
    const std::uint32_t e = entries[s.code];
    const int length = static_cast<int>(e >> 16);
    return {(e & 0xFFFFu) | (std::uint64_t{s.extra} << length), length + s.extra_bits};
  }

  void write(BitWriter& out, const Symbol& s) const {
    const auto [bits, count] = field(s);
    out.put(bits, count);
  }
};

// zlib's inflate accepts an incomplete code only in narrow cases: with two used symbols
// every code here is complete.
Code code_for(std::vector<std::uint32_t> frequency, int max_bits) {
  const auto used =
      std::count_if(frequency.begin(), frequency.end(), [](std::uint32_t f) { return f > 0; });
  for (std::size_t s = 0; used + static_cast<long>(s) < 2; ++s)
    if (frequency[s] == 0) frequency[s] = 1;
  Code code;
  code.lengths = huffman_lengths(frequency, max_bits);
  const std::vector<std::uint16_t> codes = canonical_codes(code.lengths);
  code.entries.resize(codes.size());
  for (std::size_t s = 0; s < codes.size(); ++s)
    code.entries[s] = codes[s] | (std::uint32_t{code.lengths[s]} << 16);
  return code;
}

// The code lengths of both alphabets, run-length coded with the symbols 16 (repeat the last
// length 3–6 times), 17 (3–10 zeros) and 18 (11–138 zeros) of RFC 1951, 3.2.7.
std::vector<Symbol> run_length_coded(const std::vector<std::uint8_t>& lengths) {
  std::vector<Symbol> out;
  for (std::size_t i = 0; i < lengths.size();) {
    const std::uint8_t value = lengths[i];
    std::size_t run = 1;
    while (i + run < lengths.size() && lengths[i + run] == value) ++run;
    i += run;
    if (value == 0) {
      for (; run >= 11; run -= std::min<std::size_t>(run, 138))
        out.push_back({18, 7, static_cast<std::uint16_t>(std::min<std::size_t>(run, 138) - 11)});
      if (run >= 3) out.push_back({17, 3, static_cast<std::uint16_t>(run - 3)}), run = 0;
    } else {
      out.push_back({value, 0, 0});
      --run;
      for (; run >= 3; run -= std::min<std::size_t>(run, 6))
        out.push_back({16, 2, static_cast<std::uint16_t>(std::min<std::size_t>(run, 6) - 3)});
    }
    for (; run > 0; --run) out.push_back({value, 0, 0});
  }
  return out;
}

// Writes the tokens as one block with dynamic Huffman codes (RFC 1951, 3.2.7).
void write_block(BitWriter& out, const Block& block, const std::array<Symbol, 2>& distances,
                 bool last) {
  const auto& length_symbol = length_symbols();
  const std::vector<Token>& tokens = block.tokens;
  std::vector<std::uint32_t> literal_frequency = block.literal_frequency();
  std::vector<std::uint32_t> distance_frequency(30, 0);
  for (int i = 0; i < 2; ++i) distance_frequency[distances[i].code] += block.distance_uses[i];
  literal_frequency[kEndOfBlock] = 1;
  const Code literals = code_for(literal_frequency, 15);
  const Code distance = code_for(distance_frequency, 15);

  std::size_t literal_count = 286;
  while (literal_count > 257 && literals.lengths[literal_count - 1] == 0) --literal_count;
  std::size_t distance_count = 30;
  while (distance_count > 1 && distance.lengths[distance_count - 1] == 0) --distance_count;
  std::vector<std::uint8_t> lengths(literals.lengths.begin(),
                                    literals.lengths.begin() + static_cast<long>(literal_count));
  lengths.insert(lengths.end(), distance.lengths.begin(),
                 distance.lengths.begin() + static_cast<long>(distance_count));
  const std::vector<Symbol> coded_lengths = run_length_coded(lengths);
  std::vector<std::uint32_t> length_frequency(19, 0);
  for (const Symbol& s : coded_lengths) ++length_frequency[s.code];
  const Code length_code = code_for(length_frequency, 7);
  static constexpr std::array<int, 19> kOrder = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                                 11, 4,  12, 3, 13, 2, 14, 1, 15};
  std::size_t order_count = 19;
  while (order_count > 4 && length_code.lengths[kOrder[order_count - 1]] == 0) --order_count;

  // At most 15 + 5 + 15 + 13 bits a token, and the header's 19 + 3 · 19 + 316 · 14 bits.
  out.reserve(tokens.size() * 6 + 1024);
  out.put(last ? 1 : 0, 1);
  out.put(2, 2);  // dynamic Huffman codes
  out.put(literal_count - 257, 5);
  out.put(distance_count - 1, 5);
  out.put(order_count - 4, 4);
  out.flush();
  for (std::size_t i = 0; i < order_count; ++i) {
    out.put(length_code.lengths[kOrder[i]], 3);
    out.flush();
  }
  for (const Symbol& s : coded_lengths) {
    length_code.write(out, s);
    out.flush();
  }
  // Each match length's and each distance's code with its extra bits, looked up once a token.
  std::array<std::pair<std::uint64_t, int>, kMaxLength + 1> length_field{};
  for (int length = kMinLength; length <= kMaxLength; ++length)
    length_field[static_cast<std::size_t>(length)] = literals.field(length_symbol[length]);
  const std::array<std::pair<std::uint64_t, int>, 2> distance_field = {
      distance.field(distances[0]), distance.field(distances[1])};
  for (Token t : tokens) {
    if (t & kMatch) {
      const auto& [length_bits, length_count] = length_field[match_length(t)];
      const auto& [distance_bits, distance_count] = distance_field[match_above(t) ? 1 : 0];
      out.put(length_bits, length_count);
      out.put(distance_bits, distance_count);
    } else {
      literals.write(out, Symbol{static_cast<std::uint16_t>(t), 0, 0});
    }
    out.flush();
  }
  literals.write(out, Symbol{kEndOfBlock, 0, 0});
  out.flush();
}

// Appends a run of `bytes` repeated bytes as matches of at most 258, leaving no piece shorter
// than 3 (what is left under 3 bytes goes as literals of `row`, from `at`).
void push_run(Block& block, int bytes, bool above, const std::uint8_t* row, std::size_t at) {
  while (bytes >= kMinLength) {
    int length = std::min(bytes, kMaxLength);
    if (bytes - length > 0 && bytes - length < kMinLength) length = bytes - kMinLength;
    block.repeat(length, above);
    bytes -= length;
    at += static_cast<std::size_t>(length);
  }
  for (; bytes > 0; --bytes) block.literal(row[at++]);
}

// The number of pixels from x on whose keys equal those of `other` at the same index, four at a
// time where SSE2 is there (every x86-64).
int equal_run(const std::uint32_t* keys, const std::uint32_t* other, int x, int width,
              std::uint32_t mask) {
  int n = x;
#if defined(__SSE2__)
  const __m128i m = _mm_set1_epi32(static_cast<int>(mask));
  for (; n + 4 <= width; n += 4) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(keys + n));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(other + n));
    const __m128i differ = _mm_and_si128(_mm_xor_si128(a, b), m);
    const int equal = _mm_movemask_epi8(_mm_cmpeq_epi32(differ, _mm_setzero_si128()));
    if (equal != 0xFFFF) return n - x + __builtin_ctz(~static_cast<unsigned>(equal)) / 4;
  }
#endif
  while (n < width && ((keys[n] ^ other[n]) & mask) == 0) ++n;
  return n - x;
}

// The tokens of one row (after its filter byte): each pixel matched against the one above
// (`above`, or none) and the one to its left, the longer run taken; a pixel neither repeats is
// sent as literals.
void encode_row(Block& block, const std::uint32_t* keys, const std::uint32_t* above, int width,
                std::uint32_t mask, int channels, const std::uint8_t* row) {
  for (int x = 0; x < width;) {
    // Most pixels that repeat neither neighbour are a curve's or a glyph's edge: decided here
    // without the run scans.
    const bool same_up = above && ((keys[x] ^ above[x]) & mask) == 0;
    const bool same_left = x > 0 && ((keys[x] ^ keys[x - 1]) & mask) == 0;
    if (!same_up && !same_left) {
      const std::size_t at = static_cast<std::size_t>(x) * channels;
      for (int c = 0; c < channels; ++c) block.literal(row[at + c], c);
      ++x;
      continue;
    }
    const int up = same_up ? equal_run(keys, above, x, width, mask) : 0;
    // A long match above is taken as it is: a longer one to the left would save a few bits.
    const int left = same_left && up < kLongRun ? equal_run(keys, keys - 1, x, width, mask) : 0;
    const std::size_t at = static_cast<std::size_t>(x) * channels;
    const int run = std::max(up, left);
    push_run(block, run * channels, up >= left, row, at);
    x += run;
  }
}

}  // namespace

std::vector<std::uint8_t> zlib_image_rows(const ImageRows& image) {
  const int channels = image.channels;
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * channels;
  // The pixel above lies one row and its filter byte back; too far back for DEFLATE in rows
  // wider than 32 KiB, which then match to the left only.
  const bool can_match_above = row_bytes + 1 <= kMaxDistance;
  const std::array<Symbol, 2> distances = {
      distance_symbol(channels),
      distance_symbol(can_match_above ? static_cast<int>(row_bytes + 1) : 1)};

  std::vector<std::uint8_t> out = {0x78, 0x01};  // zlib header: DEFLATE, 32 KiB window
  BitWriter bits(out);
  Block block;
  block.tokens.reserve(kBlockTokens + row_bytes + 1);
  std::vector<std::uint8_t> row(row_bytes);
  std::uint32_t adler = 1;
  const std::uint8_t filter = 0;
  for (int y = 0; y < image.height; ++y) {
    const std::uint32_t* keys = image.keys + static_cast<std::size_t>(y) * image.key_stride;
    const std::uint32_t* above = y > 0 && can_match_above ? keys - image.key_stride : nullptr;
    // A row the same as the one above is one match, and `row` holds its bytes already.
    const bool repeats_above = y > 0 && equal_run(keys, keys - image.key_stride, 0, image.width,
                                                  image.key_mask) == image.width;
    if (!repeats_above) image.row(image.source, y, row.data());
    adler = libdeflate_adler32(adler, &filter, 1);
    adler = libdeflate_adler32(adler, row.data(), row_bytes);
    block.literal(filter, 3);
    if (repeats_above && above) {
      push_run(block, static_cast<int>(row_bytes), true, row.data(), 0);
    } else {
      encode_row(block, keys, above, image.width, image.key_mask, channels, row.data());
    }
    if (block.tokens.size() >= kBlockTokens) {
      write_block(bits, block, distances, false);
      block.clear();
    }
  }
  write_block(bits, block, distances, true);
  bits.finish();
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(adler >> shift));
  return out;
}

}  // namespace vibro::render
