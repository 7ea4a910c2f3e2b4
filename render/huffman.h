// Huffman codes for DEFLATE (RFC 1951): code lengths limited to a maximum from symbol
// frequencies, and the canonical codes those lengths define, bit-reversed for DEFLATE's
// least-significant-bit-first order.
#pragma once

#include <cstdint>
#include <vector>

namespace vibro::render {

// Code lengths (0 for an unused symbol) of a Huffman code over `frequencies`, none longer than
// `max_bits`. Where the optimal code is too deep, the frequencies are halved (keeping every used
// symbol used) until it fits: the code stays complete and within a few per cent of optimal on
// the skewed statistics of figures. A single used symbol gets length 1 (DEFLATE allows one
// one-bit code); no used symbol gives all zeros.
std::vector<std::uint8_t> huffman_lengths(const std::vector<std::uint32_t>& frequencies,
                                          int max_bits);

// The canonical code of each symbol (RFC 1951, 3.2.2), bit-reversed so that writing its
// `lengths[s]` low bits first puts the code's most significant bit first in the stream.
std::vector<std::uint16_t> canonical_codes(const std::vector<std::uint8_t>& lengths);

}  // namespace vibro::render
