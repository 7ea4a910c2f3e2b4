// The edge-value fuzzer for orbit and sweep requests (docs/ROBUSTNESS.md, "Edge values in orbit
// and sweep requests"): every bounded numeric field these requests read, and every model field
// they can sweep or continue, at each edge of its bound (edge_values.h) and in pairs of edges,
// from a few base scenes, carried out as the server carries them out (edge_requests.h) with a
// deadline of 300 ms. Deterministic; VIBRO_EDGE_FRACTION in (0, 1] checks that share of the
// requests (the sanitizer build checks a quarter by default); VIBRO_EDGE_TRACE set prints each
// request before it runs.
#include "tests/robustness/edge_requests.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/run/validate.h"
#include "io/presets.h"
#include "tests/robustness/edge_values.h"
#include "tests/sanitizers.h"

namespace vibro::robustness {
namespace {

using nlohmann::json;

constexpr double kDefaultFraction = vibro::testing::kUnderAsan ? 0.25 : 1.0;

double fraction() {
  const char* s = std::getenv("VIBRO_EDGE_FRACTION");
  const double f = s ? std::strtod(s, nullptr) : kDefaultFraction;
  return f > 0.0 && f <= 1.0 ? f : kDefaultFraction;
}

server::Limits limits() {
  server::Limits l;
  l.deadline_ms = 300.0;
  return l;
}

// A model field and the bound validate_model holds it to (core/run/validate.cpp).
struct Bounded {
  std::string path;  // "model.pellets[0].F0"
  double lo, hi;
};

std::vector<Bounded> model_fields(const json& model) {
  std::vector<Bounded> fields = {{"model.g", 0.0, 1e4},
                                 {"model.R", 0.0, 1e6},
                                 {"model.alpha0", 0.0, std::numbers::pi / 2},
                                 {"model.k_c", 0.0, 1.0},
                                 {"model.mu_s", 0.0, 1e6}};
  for (std::size_t i = 0; i < model["pellets"].size(); ++i) {
    const std::string p = "model.pellets[" + std::to_string(i) + "].";
    fields.push_back({p + "m", 0.0, 1e12});
    fields.push_back({p + "phi0", -kMaxStartAngle, kMaxStartAngle});
    fields.push_back({p + "dphi0", -kMaxStartSpeed, kMaxStartSpeed});
    fields.push_back({p + "F0", -1e12, 1e12});
    fields.push_back({p + "Omega", -1e9, 1e9});
    fields.push_back({p + "psi", -1e4, 1e4});
  }
  for (std::size_t j = 0; j < model["limiters"].size(); ++j) {
    const std::string l = "model.limiters[" + std::to_string(j) + "].";
    fields.push_back({l + "angle", -1e4, 1e4});
    fields.push_back({l + "k", 0.0, 1.0});
  }
  return fields;
}

// The JSON value at a field path of the request, made if absent.
json& slot(json& request, const std::string& path) { return *field_at(request, path, true); }

json preset(const char* name) {
  json scene = json::parse(*preset_json(name));
  scene.erase("description");
  scene.erase("assumptions");
  return scene;
}

// The base scenes: the impact oscillator (one pellet, one stop) and the paper's scene (two
// pellets, two limiters, its mobile one made fixed for the orbits), each with a short request
// of its own so that most requests finish well inside the deadline.
struct Base {
  std::string name;
  json orbit;                // a scene with "periodic_orbit", without "continuation"
  json continuation;         // the same with one
  std::vector<json> sweeps;  // scenes with "sweep"; the first also sweeps the model's fields
};

std::vector<Base> bases() {
  json io = preset("impact-oscillator");
  io.erase("sweep");
  io["periodic_orbit"] = {{"periods", 1}, {"transient", 40}, {"max_iterations", 40}};
  json io_cont = io;
  io_cont["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"}, {"to", 5.5}, {"max_points", 6}};
  json io_sweep = preset("impact-oscillator");
  io_sweep.erase("periodic_orbit");
  io_sweep["sweep"]["count"] = 3;
  io_sweep["sweep"]["transient"] = 10;
  io_sweep["sweep"]["record"] = 5;

  json paper = preset("paper");
  paper["model"]["limiters"][0].erase("mobile");
  paper["model"]["limiters"][0].erase("rearm_by");
  paper["periodic_orbit"] = {{"periods", 1}, {"transient", 20}, {"max_iterations", 40}};
  json paper_cont = paper;
  paper_cont["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].F0"}, {"to", 1.3}, {"max_points", 6}};
  json paper_sweep = preset("paper-bifurcation");
  paper_sweep["sweep"]["count"] = 3;
  paper_sweep["sweep"]["transient"] = 5;
  paper_sweep["sweep"]["record"] = 5;

  json impact_sweep = io_sweep;
  impact_sweep["sweep"]["section"] = "impact";
  impact_sweep["sweep"]["continuation"] = "none";
  impact_sweep["sweep"]["lyapunov"] = true;
  return {{"impact-oscillator", io, io_cont, {io_sweep, impact_sweep}},
          {"paper", paper, paper_cont, {paper_sweep}}};
}

enum class Kind { orbit, sweep };

// Findings in code these tests may not fix, open in an issue: printed with an example, not
// failed, until their fix lands. None is open now.
struct Open {
  Kind kind;
  const char* starts;  // how the finding begins
  const char* what;
};
constexpr std::array<Open, 0> kOpen{};

const Open* open_finding(Kind kind, const std::string& finding) {
  for (const Open& o : kOpen)
    if (o.kind == kind && finding.starts_with(o.starts)) return &o;
  return nullptr;
}

// Carries out requests (the share fraction() picks, evenly), and reports what they broke.
class Fuzz {
 public:
  explicit Fuzz(std::string name) : name_(std::move(name)), keep_(fraction()) {}

  // `request` with the edge values in place of its markers.
  void add(Kind kind, const json& request, const std::vector<Edge>& edges) {
    const double place = std::fmod(static_cast<double>(seen_++) * 0.6180339887498949, 1.0);
    if (place >= keep_) return;
    const std::string body = with_edges(request, edges);
    // A request that crashes the test is named only if it is written before it runs.
    if (trace_) std::cout << "[ request  ] " << body << std::endl;
    const EdgeOutcome out =
        kind == Kind::orbit ? orbit_request(body, limits_) : sweep_request(body, limits_);
    ++run_;
    accepted_ += out.accepted;
    if (out.ms > 2.0 * limits_.deadline_ms)
      std::cout << "[ slow     ] " << std::lround(out.ms) << " ms: " << body << "\n";
    slowest_ms_ = std::max(slowest_ms_, out.ms);
    for (const std::string& f : out.findings) {
      const std::string finding =
          std::string(kind == Kind::orbit ? "orbit" : "sweep") + " request " + body + "\n    " + f;
      if (const Open* o = open_finding(kind, f)) {
        if (open_[o->what]++ == 0) open_example_[o->what] = finding;
      } else {
        findings_.push_back(finding);
      }
    }
  }

  ~Fuzz() {
    std::cout << "[ edges    ] " << name_ << ": " << run_ << " of " << seen_ << " requests, "
              << accepted_ << " accepted, slowest " << std::lround(slowest_ms_) << " ms, "
              << findings_.size() << " findings\n";
    for (const auto& [what, count] : open_)
      std::cout << "[ open     ] " << count << " × " << what << "; e.g. " << open_example_[what]
                << "\n";
    for (const std::string& f : findings_) ADD_FAILURE() << f;
  }

 private:
  std::string name_;
  double keep_;
  bool trace_ = std::getenv("VIBRO_EDGE_TRACE") != nullptr;
  server::Limits limits_ = limits();
  long seen_ = 0, run_ = 0, accepted_ = 0;
  double slowest_ms_ = 0.0;
  std::vector<std::string> findings_;
  std::map<std::string, long> open_;
  std::map<std::string, std::string> open_example_;
};

// The request with `path` holding marker 0, for each edge.
void each_edge(Fuzz& fuzz, Kind kind, json request, const std::string& path,
               const std::vector<Edge>& edges) {
  slot(request, path) = marker(0);
  for (const Edge& e : edges) fuzz.add(kind, request, {e});
}

// The request with `a` and `b` holding markers 0 and 1, for every pair of their edges.
void each_pair(Fuzz& fuzz, Kind kind, json request, const std::string& a,
               const std::vector<Edge>& a_edges, const std::string& b,
               const std::vector<Edge>& b_edges) {
  slot(request, a) = marker(0);
  slot(request, b) = marker(1);
  for (const Edge& x : a_edges)
    for (const Edge& y : b_edges) fuzz.add(kind, request, {x, y});
}

// The request with the ends of a range, `from` and `to`, at span_pairs of the field's bound.
void each_span(Fuzz& fuzz, Kind kind, json request, const std::string& from, const std::string& to,
               const Bounded& field) {
  slot(request, from) = marker(0);
  slot(request, to) = marker(1);
  for (const auto& [a, b] : span_pairs(field.lo, field.hi)) fuzz.add(kind, request, {a, b});
}

// Field paths a request may name a parameter by, at the edges of the model's lists.
std::vector<std::string> parameter_edges(const json& model) {
  const std::string n = std::to_string(model["pellets"].size());
  const std::string m = std::to_string(model["limiters"].size());
  return {"model.pellets[" + n + "].F0",
          "model.limiters[" + m + "].k",
          "model.pellets[18446744073709551616].F0",
          "model.pellets[1000001].m",
          "model.pellets[-1].m",
          "model.pellets[0].",
          "model.pellets[].m",
          "model.",
          "model",
          "model.mu_s",
          ""};
}

TEST(EdgeRequests, OrbitFieldsAtTheirEdges) {
  Fuzz fuzz("orbit fields");
  for (const Base& b : bases()) {
    for (const json* base : {&b.orbit, &b.continuation}) {
      each_edge(fuzz, Kind::orbit, *base, "periodic_orbit.periods", whole_edges(1, 64));
      each_edge(fuzz, Kind::orbit, *base, "periodic_orbit.max_iterations", whole_edges(1, 1000));
      json guessed = *base;
      for (const json& p : (*base)["model"]["pellets"])
        guessed["periodic_orbit"]["guess"].push_back(
            {{"phi", p["phi0"]}, {"dphi", p.value("dphi0", 0.0)}});
      const std::string last =
          "periodic_orbit.guess[" + std::to_string(guessed["model"]["pellets"].size() - 1) + "]";
      for (const std::string& g : {std::string("periodic_orbit.guess[0]"), last}) {
        each_edge(fuzz, Kind::orbit, guessed, g + ".phi",
                  number_edges(-kMaxStartAngle, kMaxStartAngle));
        each_edge(fuzz, Kind::orbit, guessed, g + ".dphi",
                  number_edges(-kMaxStartSpeed, kMaxStartSpeed));
      }
      each_pair(fuzz, Kind::orbit, guessed, "periodic_orbit.guess[0].phi",
                pair_edges(-kMaxStartAngle, kMaxStartAngle), "periodic_orbit.guess[0].dphi",
                pair_edges(-kMaxStartSpeed, kMaxStartSpeed));
      each_pair(fuzz, Kind::orbit, *base, "periodic_orbit.periods", pair_edges(1, 64),
                "periodic_orbit.max_iterations", pair_edges(1, 1000));
    }
    each_edge(fuzz, Kind::orbit, b.orbit, "periodic_orbit.transient", whole_edges(0, 100000));
    each_pair(fuzz, Kind::orbit, b.orbit, "periodic_orbit.transient", pair_edges(0, 100000),
              "periodic_orbit.periods", pair_edges(1, 64));
  }
}

TEST(EdgeRequests, ContinuationFieldsAtTheirEdges) {
  Fuzz fuzz("continuation fields");
  for (const Base& b : bases()) {
    const json& base = b.continuation;
    each_edge(fuzz, Kind::orbit, base, "periodic_orbit.continuation.max_points",
              whole_edges(2, 10000));
    each_pair(fuzz, Kind::orbit, base, "periodic_orbit.continuation.max_points",
              pair_edges(2, 10000), "periodic_orbit.periods", pair_edges(1, 64));
    for (const std::string& p : parameter_edges(base["model"])) {
      json request = base;
      request["periodic_orbit"]["continuation"]["parameter"] = p;
      fuzz.add(Kind::orbit, request, {});
    }
    // Each model field continued to each edge of its bound, and from one edge to another.
    for (const Bounded& f : model_fields(base["model"])) {
      json request = base;
      request["periodic_orbit"]["continuation"]["parameter"] = f.path;
      each_edge(fuzz, Kind::orbit, request, "periodic_orbit.continuation.to",
                number_edges(f.lo, f.hi));
      each_span(fuzz, Kind::orbit, request, f.path, "periodic_orbit.continuation.to", f);
    }
  }
}

TEST(EdgeRequests, SweepFieldsAtTheirEdges) {
  Fuzz fuzz("sweep fields");
  for (const Base& b : bases())
    for (const json& base : b.sweeps) {
      each_edge(fuzz, Kind::sweep, base, "sweep.count", whole_edges(1, 10000000));
      each_edge(fuzz, Kind::sweep, base, "sweep.transient", whole_edges(0, 1000000));
      each_edge(fuzz, Kind::sweep, base, "sweep.record", whole_edges(1, 1000000));
      each_edge(fuzz, Kind::sweep, base, "sweep.initial_states", whole_edges(1, 1000));
      each_edge(fuzz, Kind::sweep, base, "sweep.seed", whole_edges(0, 1000000000));
      for (const std::string& p : parameter_edges(base["model"])) {
        json request = base;
        request["sweep"]["parameter"] = p;
        fuzz.add(Kind::sweep, request, {});
      }
      json grid = base;
      grid["sweep"]["parameter2"] = {
          {"parameter", "model.limiters[0].k"}, {"from", 0.5}, {"to", 0.9}, {"count", 2}};
      each_edge(fuzz, Kind::sweep, grid, "sweep.parameter2.count", whole_edges(1, 10000000));
      each_edge(fuzz, Kind::sweep, grid, "sweep.parameter2.from", number_edges(0.0, 1.0));
      each_edge(fuzz, Kind::sweep, grid, "sweep.parameter2.to", number_edges(0.0, 1.0));
      each_pair(fuzz, Kind::sweep, base, "sweep.count", pair_edges(1, 10000000), "sweep.record",
                pair_edges(1, 1000000));
      each_pair(fuzz, Kind::sweep, base, "sweep.count", pair_edges(1, 10000000),
                "sweep.initial_states", pair_edges(1, 1000));
      each_pair(fuzz, Kind::sweep, base, "sweep.transient", pair_edges(0, 1000000), "sweep.record",
                pair_edges(1, 1000000));
      each_pair(fuzz, Kind::sweep, grid, "sweep.count", pair_edges(1, 10000000),
                "sweep.parameter2.count", pair_edges(1, 10000000));
    }
}

TEST(EdgeRequests, SweepsOfEveryModelFieldToItsEdges) {
  Fuzz fuzz("swept model fields");
  for (const Base& b : bases()) {
    for (const Bounded& f : model_fields(b.sweeps[0]["model"])) {
      json request = b.sweeps[0];
      request["sweep"]["parameter"] = f.path;
      slot(request, "sweep.from") = marker(0);
      slot(request, "sweep.to") = marker(0);
      for (const Edge& e : number_edges(f.lo, f.hi)) fuzz.add(Kind::sweep, request, {e});
      each_span(fuzz, Kind::sweep, request, "sweep.from", "sweep.to", f);
    }
  }
}

TEST(EdgeRequests, ModelFieldsAtTheirEdgesUnderOrbitsAndSweeps) {
  Fuzz fuzz("model fields");
  for (const Base& b : bases()) {
    for (const Bounded& f : model_fields(b.orbit["model"]))
      each_edge(fuzz, Kind::orbit, b.orbit, f.path, number_edges(f.lo, f.hi));
    for (const Bounded& f : model_fields(b.sweeps[0]["model"]))
      each_edge(fuzz, Kind::sweep, b.sweeps[0], f.path, number_edges(f.lo, f.hi));
  }
}

// The requests added since the fuzzer was written: an orbit with a mobile limiter (its armed
// states), a basin map (classify: attractor) and a two-parameter curve (follow).
json mobile_orbit() {
  json paper = preset("paper");
  paper["periodic_orbit"] = {{"periods", 1}, {"transient", 20}, {"max_iterations", 40}};
  return paper;
}

json basin_sweep() {
  json io = preset("impact-oscillator");
  io.erase("periodic_orbit");
  io["sweep"] = {
      {"parameter", "model.pellets[0].phi0"},
      {"from", 0.01},
      {"to", 1.6},
      {"count", 3},
      {"parameter2",
       {{"parameter", "model.pellets[0].dphi0"}, {"from", -8.0}, {"to", 8.0}, {"count", 3}}},
      {"transient", 10},
      {"record", 5},
      {"continuation", "none"},
      {"classify", "attractor"}};
  return io;
}

json followed_curve() {
  json io = preset("impact-oscillator");
  io.erase("sweep");
  io["model"]["pellets"][0]["Omega"] = 6.0;
  io["periodic_orbit"] = {
      {"periods", 1},
      {"transient", 40},
      {"max_iterations", 40},
      {"guess", {{{"phi", 0.15}, {"dphi", 0.1}}}},
      {"continuation",
       {{"parameter", "model.pellets[0].Omega"},
        {"to", 5.0},
        {"max_points", 4},
        {"follow", "period_doubling"},
        {"parameter2", {{"parameter", "model.limiters[0].k"}, {"from", 0.6}, {"to", 0.95}}}}}};
  return io;
}

TEST(EdgeRequests, ArmedStatesOfAMobileLimiterOrbit) {
  Fuzz fuzz("mobile-limiter orbit");
  const json base = mobile_orbit();
  for (const json& armed :
       {json::array(), json{true}, json{false, false}, json{true, true}, json{true, true, true},
        json{1, 0}, json{"yes", true}, json(true), json::object()}) {
    json request = base;
    request["periodic_orbit"]["armed"] = armed;
    fuzz.add(Kind::orbit, request, {});
    request["model"]["limiters"][0]["armed"] = false;
    fuzz.add(Kind::orbit, request, {});
  }
  json guessed = base;
  for (const json& p : base["model"]["pellets"])
    guessed["periodic_orbit"]["guess"].push_back(
        {{"phi", p["phi0"]}, {"dphi", p.value("dphi0", 0.0)}});
  guessed["periodic_orbit"]["armed"] = {false, true};
  for (const char* g : {"periodic_orbit.guess[0].phi", "periodic_orbit.guess[1].phi"})
    each_edge(fuzz, Kind::orbit, guessed, g, number_edges(-kMaxStartAngle, kMaxStartAngle));
  // A guess exactly at each limiter's angle, armed and not.
  for (const json& limiter : base["model"]["limiters"]) {
    json request = guessed;
    request["periodic_orbit"]["guess"][0]["phi"] = limiter["angle"];
    request["periodic_orbit"]["guess"][0]["dphi"] = 0.0;
    fuzz.add(Kind::orbit, request, {});
  }
  json continued = base;
  continued["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].F0"}, {"to", 1.3}, {"max_points", 4}};
  each_edge(fuzz, Kind::orbit, continued, "periodic_orbit.continuation.to",
            number_edges(-1e12, 1e12));
}

TEST(EdgeRequests, BasinMapsAtTheirEdges) {
  Fuzz fuzz("basin maps");
  const json base = basin_sweep();
  each_edge(fuzz, Kind::sweep, base, "sweep.count", whole_edges(1, 10000000));
  each_edge(fuzz, Kind::sweep, base, "sweep.parameter2.count", whole_edges(1, 10000000));
  each_edge(fuzz, Kind::sweep, base, "sweep.record", whole_edges(1, 1000000));
  each_pair(fuzz, Kind::sweep, base, "sweep.count", pair_edges(1, 10000000),
            "sweep.parameter2.count", pair_edges(1, 10000000));
  each_span(fuzz, Kind::sweep, base, "sweep.from", "sweep.to",
            {"model.pellets[0].phi0", -kMaxStartAngle, kMaxStartAngle});
  each_span(fuzz, Kind::sweep, base, "sweep.parameter2.from", "sweep.parameter2.to",
            {"model.pellets[0].dphi0", -kMaxStartSpeed, kMaxStartSpeed});
  for (const json& classify : {json("attractor"), json("period"), json(""), json("ATTRACTOR"),
                               json(1), json(nullptr), json::array()}) {
    json request = base;
    request["sweep"]["classify"] = classify;
    fuzz.add(Kind::sweep, request, {});
  }
  // Classifying over a parameter of the model instead of an initial state, over one parameter
  // alone, and with the other sweep options it may or may not go with.
  for (const std::string& p : parameter_edges(base["model"])) {
    json request = base;
    request["sweep"]["parameter"] = p;
    fuzz.add(Kind::sweep, request, {});
  }
  for (const auto& [path, value] :
       std::vector<std::pair<std::string, json>>{{"sweep.parameter", "model.pellets[0].F0"},
                                                 {"sweep.parameter2", nullptr},
                                                 {"sweep.continuation", "up"},
                                                 {"sweep.section", "impact"},
                                                 {"sweep.lyapunov", true},
                                                 {"sweep.initial_states", 4}}) {
    json request = base;
    if (value.is_null())
      request["sweep"].erase("parameter2");
    else
      slot(request, path) = value;
    fuzz.add(Kind::sweep, request, {});
  }
}

TEST(EdgeRequests, FollowedCurvesAtTheirEdges) {
  Fuzz fuzz("followed curves");
  const json base = followed_curve();
  for (const json& kind : {json("fold"), json("period_doubling"), json("grazing"),
                           json("neimark_sacker"), json(""), json(2), json(nullptr)}) {
    json request = base;
    request["periodic_orbit"]["continuation"]["follow"] = kind;
    fuzz.add(Kind::orbit, request, {});
  }
  json alone = base;
  alone["periodic_orbit"]["continuation"].erase("parameter2");
  fuzz.add(Kind::orbit, alone, {});
  each_edge(fuzz, Kind::orbit, base, "periodic_orbit.continuation.max_points",
            whole_edges(2, 10000));
  for (const std::string& p : parameter_edges(base["model"])) {
    json request = base;
    request["periodic_orbit"]["continuation"]["parameter2"]["parameter"] = p;
    fuzz.add(Kind::orbit, request, {});
  }
  for (const Bounded& f : model_fields(base["model"])) {
    json request = base;
    request["periodic_orbit"]["continuation"]["parameter2"]["parameter"] = f.path;
    each_span(fuzz, Kind::orbit, request, "periodic_orbit.continuation.parameter2.from",
              "periodic_orbit.continuation.parameter2.to", f);
  }
  // The second parameter the same as the first.
  json same = base;
  same["periodic_orbit"]["continuation"]["parameter2"]["parameter"] = "model.pellets[0].Omega";
  fuzz.add(Kind::orbit, same, {});
}

// Issue 31 item 7 at the edge of a bound: the third value of a sweep from -9999.999999999998 to
// 10000 (count 3) was 10000.000000000002, past both `to` and phi0's bound of 1e4, and was run
// (SweepAxis::value: the last value is now `to`, the others kept within [from, to]).
TEST(EdgeRequests, SweepValuesStayInsideTheirRange) {
  json request = bases()[0].sweeps[0];
  request["sweep"]["parameter"] = "model.pellets[0].phi0";
  request["sweep"]["from"] = -9999.999999999998;
  request["sweep"]["to"] = 10000.0;
  const EdgeOutcome out = sweep_request(request.dump(), limits());
  EXPECT_TRUE(out.accepted) << out.field << " " << out.message;
  for (const std::string& f : out.findings) ADD_FAILURE() << f;
}

}  // namespace
}  // namespace vibro::robustness
