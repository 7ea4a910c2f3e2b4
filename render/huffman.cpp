#include "render/huffman.h"

#include <algorithm>

namespace vibro::render {
namespace {

// Depths of the leaves of a Huffman tree over the used symbols (ascending frequency), built by
// the two-queue method: leaves in order, merged nodes in the order they are made.
std::vector<int> tree_depths(const std::vector<std::uint32_t>& sorted_frequency) {
  const std::size_t n = sorted_frequency.size();
  // Nodes 0..n-1 are leaves, n.. are merged nodes; parent[] links each node to its merge.
  std::vector<std::uint64_t> weight(sorted_frequency.begin(), sorted_frequency.end());
  weight.reserve(2 * n);
  std::vector<std::size_t> parent(2 * n - 1, 0);
  std::size_t next_leaf = 0;
  std::size_t next_node = n;
  const auto take = [&]() {
    if (next_leaf < n && (next_node >= weight.size() || weight[next_leaf] <= weight[next_node]))
      return next_leaf++;
    return next_node++;
  };
  for (std::size_t merges = 0; merges + 1 < n; ++merges) {
    const std::size_t a = take();
    const std::size_t b = take();
    parent[a] = parent[b] = weight.size();
    weight.push_back(weight[a] + weight[b]);
  }
  // The root is the last node; a node's depth is its parent's plus one.
  std::vector<int> depth(weight.size(), 0);
  for (std::size_t i = weight.size() - 1; i-- > 0;) depth[i] = depth[parent[i]] + 1;
  depth.resize(n);
  return depth;
}

}  // namespace

std::vector<std::uint8_t> huffman_lengths(const std::vector<std::uint32_t>& frequencies,
                                          int max_bits) {
  std::vector<std::uint8_t> lengths(frequencies.size(), 0);
  std::vector<std::size_t> used;
  for (std::size_t s = 0; s < frequencies.size(); ++s)
    if (frequencies[s] > 0) used.push_back(s);
  if (used.empty()) return lengths;
  if (used.size() == 1) {
    lengths[used[0]] = 1;
    return lengths;
  }
  std::vector<std::uint32_t> frequency(frequencies);
  for (;;) {
    std::stable_sort(used.begin(), used.end(),
                     [&](std::size_t a, std::size_t b) { return frequency[a] < frequency[b]; });
    std::vector<std::uint32_t> sorted(used.size());
    for (std::size_t i = 0; i < used.size(); ++i) sorted[i] = frequency[used[i]];
    const std::vector<int> depth = tree_depths(sorted);
    if (*std::max_element(depth.begin(), depth.end()) <= max_bits) {
      for (std::size_t i = 0; i < used.size(); ++i)
        lengths[used[i]] = static_cast<std::uint8_t>(depth[i]);
      return lengths;
    }
    // Flatter statistics give a shallower tree; equal frequencies give depth ⌈log2 n⌉.
    for (std::size_t s : used) frequency[s] = (frequency[s] + 1) / 2;
  }
}

std::vector<std::uint16_t> canonical_codes(const std::vector<std::uint8_t>& lengths) {
  constexpr int kMaxBits = 15;
  int count[kMaxBits + 1] = {};
  for (std::uint8_t l : lengths) ++count[l];
  count[0] = 0;
  int next[kMaxBits + 2] = {};
  int code = 0;
  for (int bits = 1; bits <= kMaxBits; ++bits) {
    code = (code + count[bits - 1]) << 1;
    next[bits] = code;
  }
  std::vector<std::uint16_t> codes(lengths.size(), 0);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    const int l = lengths[s];
    if (l == 0) continue;
    unsigned c = static_cast<unsigned>(next[l]++);
    unsigned reversed = 0;
    for (int i = 0; i < l; ++i, c >>= 1) reversed = (reversed << 1) | (c & 1u);
    codes[s] = static_cast<std::uint16_t>(reversed);
  }
  return codes;
}

}  // namespace vibro::render
