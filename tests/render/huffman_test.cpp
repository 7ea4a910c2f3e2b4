#include "render/huffman.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace vibro::render {
namespace {

// Σ 2^-length over the used symbols: 1 for a complete prefix code.
double kraft_sum(const std::vector<std::uint8_t>& lengths) {
  double sum = 0;
  for (std::uint8_t l : lengths)
    if (l > 0) sum += std::ldexp(1.0, -l);
  return sum;
}

double coded_bits(const std::vector<std::uint32_t>& f, const std::vector<std::uint8_t>& l) {
  double bits = 0;
  for (std::size_t s = 0; s < f.size(); ++s) bits += static_cast<double>(f[s]) * l[s];
  return bits;
}

TEST(Huffman, RfcExampleGivesItsCanonicalCodes) {
  // RFC 1951, 3.2.2: lengths (3, 3, 3, 3, 3, 2, 4, 4) give 010 011 100 101 110 00 1110 1111.
  const std::vector<std::uint8_t> lengths = {3, 3, 3, 3, 3, 2, 4, 4};
  const std::vector<unsigned> msb_first = {0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111};
  const auto codes = canonical_codes(lengths);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    unsigned reversed = 0;
    for (int i = 0; i < lengths[s]; ++i)
      reversed |= ((msb_first[s] >> i) & 1u) << (lengths[s] - 1 - i);
    EXPECT_EQ(codes[s], reversed) << "symbol " << s;
  }
}

TEST(Huffman, OptimalLengthsOnAKnownDistribution) {
  // Frequencies 1, 1, 2, 4, 8: the optimal code has lengths 4, 4, 3, 2, 1 (cost 1·4+1·4+2·3+4·2+8).
  const std::vector<std::uint32_t> f = {1, 1, 2, 4, 8};
  const auto l = huffman_lengths(f, 15);
  EXPECT_EQ(l, (std::vector<std::uint8_t>{4, 4, 3, 2, 1}));
}

TEST(Huffman, FibonacciFrequenciesAreLimitedAndStayComplete) {
  // Fibonacci weights make the deepest unconstrained tree: 30 symbols want depth 29.
  std::vector<std::uint32_t> f = {1, 1};
  while (f.size() < 30) f.push_back(f[f.size() - 1] + f[f.size() - 2]);
  for (int max_bits : {7, 9, 15}) {
    const auto l = huffman_lengths(f, max_bits);
    EXPECT_LE(*std::max_element(l.begin(), l.end()), max_bits);
    EXPECT_DOUBLE_EQ(kraft_sum(l), 1.0);
    EXPECT_TRUE(std::all_of(l.begin(), l.end(), [](std::uint8_t x) { return x > 0; }));
  }
}

TEST(Huffman, RandomFrequenciesGiveCompleteCodesNearTheEntropy) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint32_t> f(286, 0);
    const int used = 2 + static_cast<int>(rng() % 284);
    double total = 0;
    for (int i = 0; i < used; ++i) {
      f[rng() % f.size()] += 1 + (rng() % 4 == 0 ? rng() % 100000 : rng() % 10);
    }
    const auto l = huffman_lengths(f, 15);
    double entropy = 0;
    for (auto x : f) total += x;
    for (auto x : f)
      if (x > 0) entropy -= x * std::log2(x / total);
    const long n_used = std::count_if(f.begin(), f.end(), [](auto x) { return x > 0; });
    if (n_used < 2) continue;
    EXPECT_DOUBLE_EQ(kraft_sum(l), 1.0);
    EXPECT_LE(*std::max_element(l.begin(), l.end()), 15);
    // A Huffman code costs less than one bit per symbol above the entropy.
    EXPECT_LT(coded_bits(f, l), entropy + total) << "trial " << trial;
    for (std::size_t s = 0; s < f.size(); ++s) EXPECT_EQ(f[s] > 0, l[s] > 0);
  }
}

TEST(Huffman, OneOrNoUsedSymbol) {
  EXPECT_EQ(huffman_lengths({0, 5, 0}, 15), (std::vector<std::uint8_t>{0, 1, 0}));
  EXPECT_EQ(huffman_lengths({0, 0}, 15), (std::vector<std::uint8_t>{0, 0}));
}

}  // namespace
}  // namespace vibro::render
