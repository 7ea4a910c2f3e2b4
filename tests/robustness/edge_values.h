// Values at the edges of a bound, as JSON literals: each bound exactly, one ulp inside and
// outside it, zero of both signs, tiny, huge and past the range of a double. The edge-request
// fuzzer (edge_requests_test.cpp) puts them in every bounded field of orbit and sweep requests.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace vibro::robustness {

// A value as the request spells it: `text` is the JSON literal ("1e400" is one a double cannot
// hold), `value` what it reads as (±infinity for those).
struct Edge {
  std::string text;
  double value = 0.0;
};

// The shortest literal that reads back as x ("-0", "1.0000000000000002", "1e-300").
std::string literal(double x);

// The edges of a number bounded to [lo, hi] (open or closed alike): lo and hi, one ulp either
// side of each, ±0, ±1e-300, the smallest subnormal, ±1e300, ±DBL_MAX and ±1e400; each once.
std::vector<Edge> number_edges(double lo, double hi);

// The edges of a whole number in [lo, hi]: those of number_edges (so 64.00000000000001 and 1e-300
// too), lo − 1, hi + 1, lo and hi written as 1.0, and the edges of the reader's ±1e9 and of
// 64-bit integers.
std::vector<Edge> whole_edges(long lo, long hi);

// The few edges to combine in pairs: lo, hi, one ulp inside each, one ulp outside each.
std::vector<Edge> pair_edges(double lo, double hi);

// Pairs of edges for a range's two ends (a sweep's from and to, a continuation's start and to):
// the whole range, one ulp in from one or both ends, one ulp wide at either end, one ulp past
// either end.
std::vector<std::pair<Edge, Edge>> span_pairs(double lo, double hi);

// The value at a field path of a request ("model.pellets[0].F0", "sweep.parameter2.count"), or
// null where the request holds none; with `make`, made where missing (and what leads to it).
nlohmann::json* field_at(nlohmann::json& request, const std::string& path, bool make = false);

// A field that holds edge values while a request is built: the request's JSON text with every
// marker replaced by its literal (so that "1e400" and "-0" reach the reader as written).
nlohmann::json marker(int k);
std::string with_edges(const nlohmann::json& request, const std::vector<Edge>& edges);

}  // namespace vibro::robustness
