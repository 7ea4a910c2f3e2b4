#include "tests/robustness/edge_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace vibro::robustness {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void add(std::vector<Edge>& edges, Edge e) {
  for (const Edge& have : edges)
    if (have.text == e.text) return;
  edges.push_back(std::move(e));
}

void add(std::vector<Edge>& edges, double x) { add(edges, Edge{literal(x), x}); }

std::string marker_text(int k) { return "@edge" + std::to_string(k) + "@"; }

}  // namespace

std::string literal(double x) {
  char text[32];
  return {text, std::to_chars(text, text + sizeof text, x).ptr};
}

std::vector<Edge> number_edges(double lo, double hi) {
  std::vector<Edge> edges;
  for (double b : {lo, hi}) {
    add(edges, b);
    add(edges, std::nextafter(b, -kInf));
    add(edges, std::nextafter(b, kInf));
  }
  for (double x : {0.0, -0.0, 1e-300, -1e-300, std::numeric_limits<double>::denorm_min(), 1e300,
                   -1e300, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()})
    add(edges, x);
  add(edges, Edge{"1e400", kInf});
  add(edges, Edge{"-1e400", -kInf});
  return edges;
}

std::vector<Edge> whole_edges(long lo, long hi) {
  std::vector<Edge> edges = number_edges(static_cast<double>(lo), static_cast<double>(hi));
  add(edges, static_cast<double>(lo - 1));
  add(edges, static_cast<double>(hi + 1));
  add(edges, Edge{std::to_string(lo) + ".0", static_cast<double>(lo)});
  add(edges, Edge{std::to_string(hi) + ".0", static_cast<double>(hi)});
  for (double x : {1e9, 1e9 + 1, -1e9 - 1, 2147483648.0, -2147483649.0}) add(edges, x);
  add(edges, Edge{"18446744073709551615", 18446744073709551615.0});
  add(edges, Edge{"18446744073709551616", 18446744073709551616.0});
  add(edges, Edge{"-9223372036854775809", -9223372036854775809.0});
  return edges;
}

std::vector<Edge> pair_edges(double lo, double hi) {
  std::vector<Edge> edges;
  for (double x : {lo, std::nextafter(lo, hi), std::nextafter(lo, -kInf), hi,
                   std::nextafter(hi, lo), std::nextafter(hi, kInf)})
    add(edges, x);
  return edges;
}

std::vector<std::pair<Edge, Edge>> span_pairs(double lo, double hi) {
  const auto e = [](double x) { return Edge{literal(x), x}; };
  const double lo_in = std::nextafter(lo, hi), hi_in = std::nextafter(hi, lo);
  return {{e(lo), e(hi)},
          {e(lo_in), e(hi_in)},
          {e(lo_in), e(hi)},
          {e(lo), e(hi_in)},
          {e(lo), e(lo_in)},
          {e(hi_in), e(hi)},
          {e(hi), e(lo)},
          {e(std::nextafter(lo, -kInf)), e(hi)},
          {e(lo), e(std::nextafter(hi, kInf))}};
}

nlohmann::json* field_at(nlohmann::json& request, const std::string& path, bool make) {
  nlohmann::json* node = &request;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '.') {
      ++pos;
    } else if (path[pos] == '[') {
      const std::size_t close = path.find(']', pos);
      if (close == std::string::npos || !(node->is_array() || (make && node->is_null())))
        return nullptr;
      const std::size_t i = std::strtoul(path.c_str() + pos + 1, nullptr, 10);
      if (!make && i >= node->size()) return nullptr;
      node = &(*node)[i];
      pos = close + 1;
    } else {
      const std::size_t end = std::min(path.find_first_of(".[", pos), path.size());
      const std::string key = path.substr(pos, end - pos);
      if (!make && (!node->is_object() || !node->contains(key))) return nullptr;
      node = &(*node)[key];
      pos = end;
    }
  }
  return node;
}

nlohmann::json marker(int k) { return marker_text(k); }

std::string with_edges(const nlohmann::json& request, const std::vector<Edge>& edges) {
  std::string text = request.dump();
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const std::string quoted = '"' + marker_text(static_cast<int>(k)) + '"';
    for (std::size_t at = text.find(quoted); at != std::string::npos;
         at = text.find(quoted, at + edges[k].text.size()))
      text.replace(at, quoted.size(), edges[k].text);
  }
  return text;
}

}  // namespace vibro::robustness
