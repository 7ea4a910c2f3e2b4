#include "io/orbit_json.h"

#include <string>

#include "io/json_fields.h"
#include "io/result_json.h"

namespace vibro {
namespace {

using nlohmann::json;

// A whole number; as_integer bounds it to ±1e9, so it fits an int. Ranges are validate_orbit's.
int whole(Fields& f, const std::string& key, int fallback) {
  return static_cast<int>(f.integer(key).value_or(fallback));
}

std::vector<PhasePoint> read_guess(const json& list, const std::string& path) {
  std::vector<PhasePoint> guess;
  for (std::size_t i = 0; i < list.size(); ++i) {
    Fields f(list[i], path + "[" + std::to_string(i) + "]");
    guess.push_back({f.required_number("phi"), f.required_number("dphi")});
    f.done();
  }
  return guess;
}

std::vector<bool> read_armed(const json& list, const std::string& path) {
  std::vector<bool> armed;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_boolean())
      throw FieldException(path + "[" + std::to_string(i) + "]",
                           "expected true (armed) or false (disarmed)");
    armed.push_back(list[i].get<bool>());
  }
  return armed;
}

BifurcationKind followed_kind(const std::string& name, const std::string& path) {
  for (BifurcationKind k :
       {BifurcationKind::fold, BifurcationKind::period_doubling, BifurcationKind::grazing})
    if (name == bifurcation_kind_name(k)) return k;
  throw FieldException(
      path, "expected \"fold\", \"period_doubling\" or \"grazing\", got \"" + name + "\"");
}

// The continuation's "follow" and "parameter2", which come together.
std::optional<FollowSpec> read_follow(Fields& f) {
  const auto kind = f.string("follow", 40);
  const json* second = f.value("parameter2");
  if (!kind && !second) return std::nullopt;
  if (!kind)
    throw FieldException(f.path("follow"),
                         "is required with parameter2: \"fold\", \"period_doubling\" or "
                         "\"grazing\", the bifurcation to follow in it");
  if (!second)
    throw FieldException(f.path("parameter2"),
                         "is required with follow: {\"parameter\", \"from\", \"to\"}, the "
                         "second parameter to follow the bifurcation in");
  FollowSpec spec;
  spec.kind = followed_kind(*kind, f.path("follow"));
  Fields p(*second, f.path("parameter2"));
  const auto parameter = p.string("parameter", 200);
  if (!parameter)
    throw FieldException(p.path("parameter"),
                         "is required: a field path such as \"model.limiters[0].k\"");
  spec.parameter2 = *parameter;
  spec.from = p.required_number("from");
  spec.to = p.required_number("to");
  p.done();
  return spec;
}

ContinuationSpec read_continuation(const json& j, const std::string& path,
                                   std::optional<FollowSpec>& follow) {
  Fields f(j, path);
  ContinuationSpec c;
  const auto parameter = f.string("parameter", 200);
  if (!parameter)
    throw FieldException(f.path("parameter"),
                         "is required: a field path such as \"model.pellets[0].F0\"");
  c.parameter = *parameter;
  c.to = f.required_number("to");
  c.max_points = whole(f, "max_points", c.max_points);
  follow = read_follow(f);
  f.done();
  return c;
}

json states_json(const std::vector<PhasePoint>& states) {
  json list = json::array();
  for (const PhasePoint& p : states)
    list.push_back({{"phi", finite_number(p.phi)}, {"dphi", finite_number(p.dphi)}});
  return list;
}

json multipliers_json(const std::vector<std::complex<double>>& multipliers) {
  json list = json::array();
  for (const std::complex<double>& m : multipliers)
    list.push_back({{"re", finite_number(m.real())}, {"im", finite_number(m.imag())}});
  return list;
}

json orbit_json(const PeriodicOrbit& o) {
  json events = json::array();
  for (const Event& e : o.events) events.push_back(event_to_json(e));
  return {{"converged", o.converged},
          {"admissible", o.admissible},
          {"message", o.message},
          {"periods", o.periods},
          {"period", finite_number(o.period)},
          {"t0", finite_number(o.t0)},
          {"state", states_json(o.state)},
          {"armed", o.armed},
          {"iterations", o.iterations},
          {"residual", finite_number(o.residual)},
          {"multipliers", multipliers_json(o.multipliers)},
          {"stable", o.stable},
          {"neutral", o.neutral},
          {"exact_jacobian", o.exact_jacobian},
          {"jacobian_note", o.jacobian_note},
          {"impacts_per_period", finite_number(o.impacts_per_period)},
          {"at_rest", o.at_rest},
          {"events", events},
          {"stats", stats_to_json(o.stats)}};
}

json branch_json(const std::vector<BranchPoint>& points) {
  json list = json::array();
  for (const BranchPoint& p : points)
    list.push_back({{"value", finite_number(p.value)},
                    {"state", states_json(p.state)},
                    {"multipliers", multipliers_json(p.multipliers)},
                    {"stable", p.stable},
                    {"neutral", p.neutral},
                    {"impacts_per_period", finite_number(p.impacts_per_period)}});
  return list;
}

json bifurcations_json(const std::vector<Bifurcation>& bifurcations) {
  json list = json::array();
  for (const Bifurcation& b : bifurcations) {
    json j = {{"value", finite_number(b.value)},
              {"kind", std::string(bifurcation_kind_name(b.kind))},
              {"state", states_json(b.state)}};
    // A period doubling offers the doubled motion it sheds, to continue from.
    if (b.doubled_value)
      j["doubled"] = {{"value", finite_number(*b.doubled_value)},
                      {"state", states_json(b.doubled_state)}};
    // A grazing says which side the branch came from.
    if (b.approached_impacting)
      j["approached_from"] = *b.approached_impacting ? "impacting" : "non_impacting";
    list.push_back(std::move(j));
  }
  return list;
}

json curves_json(const std::vector<BifurcationCurve>& curves) {
  json list = json::array();
  for (const BifurcationCurve& c : curves) {
    json points = json::array();
    for (const CurvePoint& p : c.points)
      points.push_back({{"value", finite_number(p.value)}, {"value2", finite_number(p.value2)}});
    list.push_back({{"kind", std::string(bifurcation_kind_name(c.kind))},
                    {"points", std::move(points)},
                    {"reached_from", c.reached_from},
                    {"reached_to", c.reached_to},
                    {"message", c.message}});
  }
  return list;
}

}  // namespace

OrbitRequest read_orbit_request(const json& j, std::size_t max_pellets, std::size_t max_limiters) {
  Fields f(j, "periodic_orbit");
  OrbitRequest r;
  OrbitSpec& spec = r.orbit;
  spec.periods = whole(f, "periods", spec.periods);
  spec.transient = whole(f, "transient", spec.transient);
  if (const json* guess = f.array("guess", max_pellets))
    spec.guess = read_guess(*guess, f.path("guess"));
  if (const json* armed = f.array("armed", max_limiters))
    spec.armed = read_armed(*armed, f.path("armed"));
  spec.max_iterations = whole(f, "max_iterations", spec.max_iterations);
  if (const json* c = f.value("continuation"))
    r.continuation = read_continuation(*c, f.path("continuation"), r.follow);
  f.done();
  return r;
}

json orbit_request_to_json(const OrbitRequest& r) {
  json j = {{"periods", r.orbit.periods},
            {"transient", r.orbit.transient},
            {"max_iterations", r.orbit.max_iterations}};
  if (!r.orbit.guess.empty()) j["guess"] = states_json(r.orbit.guess);
  if (!r.orbit.armed.empty()) j["armed"] = r.orbit.armed;
  if (r.continuation)
    j["continuation"] = {{"parameter", r.continuation->parameter},
                         {"to", r.continuation->to},
                         {"max_points", r.continuation->max_points}};
  if (r.continuation && r.follow) {
    j["continuation"]["follow"] = std::string(bifurcation_kind_name(r.follow->kind));
    j["continuation"]["parameter2"] = {
        {"parameter", r.follow->parameter2}, {"from", r.follow->from}, {"to", r.follow->to}};
  }
  return j;
}

json orbit_result_json(const OrbitResult& result) {
  json j = {{"orbit", orbit_json(result.orbit)},
            {"branch", branch_json(result.branch.points)},
            {"bifurcations", bifurcations_json(result.branch.bifurcations)},
            {"reached", result.branch.reached},
            {"message", result.branch.message}};
  if (!result.curves.empty()) j["curves"] = curves_json(result.curves);
  return j;
}

}  // namespace vibro
