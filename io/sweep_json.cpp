#include "io/sweep_json.h"

#include <iomanip>
#include <sstream>

#include "io/json_fields.h"
#include "io/result_json.h"

namespace vibro {
namespace {

using nlohmann::json;

int bounded_int(Fields& f, const std::string& key, int fallback) {
  const auto v = f.integer(key);
  if (!v) return fallback;
  if (*v < -2147483647L || *v > 2147483647L) throw FieldException(f.path(key), "is out of range");
  return static_cast<int>(*v);
}

SweepAxis read_axis(Fields& f) {
  SweepAxis a;
  const auto parameter = f.string("parameter", 200);
  if (!parameter)
    throw FieldException(f.path("parameter"), "is required: a field path such as \"model.pellets[0].F0\"");
  a.parameter = *parameter;
  a.from = f.required_number("from");
  a.to = f.required_number("to");
  a.count = bounded_int(f, "count", 1);
  return a;
}

const char* section_name(SectionKind k) {
  return k == SectionKind::stroboscopic ? "stroboscopic" : "impact";
}

const char* continuation_name(Continuation c) {
  switch (c) {
    case Continuation::none: return "none";
    case Continuation::forward: return "forward";
    case Continuation::backward: return "backward";
    case Continuation::both: return "both";
  }
  return "none";
}

// A CSV cell: empty without an exponent, "-inf" where every perturbation dies.
std::string lyapunov_cell(const std::optional<double>& lyapunov) {
  if (!lyapunov) return "";
  std::ostringstream cell;
  cell << std::setprecision(17) << *lyapunov;  // "-inf" for −infinity, as strtod reads it back
  return cell.str();
}

}  // namespace

SweepSpec read_sweep(const json& j) {
  Fields f(j, "sweep");
  SweepSpec s;
  s.axis = read_axis(f);
  if (const json* p2 = f.value("parameter2")) {
    Fields f2(*p2, "sweep.parameter2");
    s.axis2 = read_axis(f2);
    f2.done();
  }
  s.transient = bounded_int(f, "transient", s.transient);
  s.record = bounded_int(f, "record", s.record);
  if (auto section = f.string("section", 32)) {
    if (*section == "stroboscopic") s.section = SectionKind::stroboscopic;
    else if (*section == "impact") s.section = SectionKind::impact;
    else throw FieldException("sweep.section", "must be \"stroboscopic\" or \"impact\", got \"" + *section + "\"");
  }
  if (auto c = f.string("continuation", 32)) {
    if (*c == "none") s.continuation = Continuation::none;
    else if (*c == "forward") s.continuation = Continuation::forward;
    else if (*c == "backward") s.continuation = Continuation::backward;
    else if (*c == "both") s.continuation = Continuation::both;
    else
      throw FieldException("sweep.continuation",
                           "must be \"none\", \"forward\", \"backward\" or \"both\", got \"" + *c + "\"");
  }
  s.initial_states = bounded_int(f, "initial_states", s.initial_states);
  if (auto seed = f.integer("seed")) {
    if (*seed < 0) throw FieldException("sweep.seed", "must not be negative");
    s.seed = static_cast<std::uint64_t>(*seed);
  }
  s.lyapunov = f.boolean("lyapunov", s.lyapunov);
  f.done();
  return s;
}

json sweep_to_json(const SweepSpec& s) {
  auto axis = [](const SweepAxis& a) {
    return json{{"parameter", a.parameter}, {"from", a.from}, {"to", a.to}, {"count", a.count}};
  };
  json j = axis(s.axis);
  if (s.axis2) j["parameter2"] = axis(*s.axis2);
  j["transient"] = s.transient;
  j["record"] = s.record;
  j["section"] = section_name(s.section);
  j["continuation"] = continuation_name(s.continuation);
  j["initial_states"] = s.initial_states;
  j["seed"] = s.seed;
  j["lyapunov"] = s.lyapunov;
  return j;
}

json sweep_result_json(const SweepSpec& spec, const SweepResult& result) {
  json value = json::array(), value2 = json::array(), start = json::array(),
       direction = json::array(), pellet = json::array(), t = json::array(), phi = json::array(),
       dphi = json::array(), phase = json::array(), limiter = json::array(), run_of = json::array(),
       point_trusted = json::array();
  json runs = {{"value", json::array()},          {"value2", json::array()},
               {"start", json::array()},          {"direction", json::array()},
               {"period", json::array()},         {"impacts_per_period", json::array()},
               {"at_rest", json::array()},        {"sticks", json::array()},
               {"trusted", json::array()},        {"trusted_until", json::array()},
               {"termination", json::array()},    {"message", json::array()},
               {"error_estimate", json::array()}, {"lyapunov", json::array()}};
  for (std::size_t r = 0; r < result.runs.size(); ++r) {
    const SweepRun& run = result.runs[r];
    for (const SectionPoint& p : run.points) {
      value.push_back(run.value);
      value2.push_back(run.value2);
      start.push_back(run.start);
      direction.push_back(run.direction);
      pellet.push_back(p.pellet);
      t.push_back(finite_number(p.t));
      phi.push_back(finite_number(p.phi));
      dphi.push_back(finite_number(p.dphi));
      phase.push_back(finite_number(p.phase));
      limiter.push_back(p.limiter);
      point_trusted.push_back(p.trusted);
      run_of.push_back(r);
    }
    runs["value"].push_back(run.value);
    runs["value2"].push_back(run.value2);
    runs["start"].push_back(run.start);
    runs["direction"].push_back(run.direction);
    runs["period"].push_back(run.period);
    runs["impacts_per_period"].push_back(finite_number(run.impacts_per_period));
    runs["at_rest"].push_back(run.at_rest);
    runs["sticks"].push_back(run.sticks);
    runs["trusted"].push_back(run.trusted);
    runs["trusted_until"].push_back(finite_number(run.trusted_until));
    runs["termination"].push_back(termination_name(run.termination));
    runs["message"].push_back(run.message);
    runs["error_estimate"].push_back(finite_number(run.error_estimate));
    // JSON has no −infinity: null, as for a run without an exponent (docs/SWEEPS.md).
    runs["lyapunov"].push_back(run.lyapunov ? finite_number(*run.lyapunov) : json(nullptr));
  }
  json points = {{"value", value}, {"value2", value2}, {"start", start},   {"direction", direction},
                 {"pellet", pellet}, {"t", t},          {"phi", phi},       {"dphi", dphi},
                 {"phase", phase},   {"limiter", limiter}, {"trusted", point_trusted},
                 {"run", run_of}};
  json j = {{"parameter", spec.axis.parameter}, {"section", section_name(spec.section)},
            {"points", points}, {"runs", runs},
            {"stats",
             {{"runs", result.runs.size()},
              {"points", value.size()},
              {"threads", result.threads},
              {"wall_ms", result.wall_ms},
              {"cancelled", result.cancelled}}}};
  if (spec.axis2) j["parameter2"] = spec.axis2->parameter;
  return j;
}

std::optional<PlotKind> sweep_plot_kind(const std::string& name, const SweepSpec& spec) {
  if (name.empty()) return spec.axis2 ? PlotKind::regime_map : PlotKind::bifurcation;
  if (name == "bifurcation") return PlotKind::bifurcation;
  if (name == "section") return PlotKind::section;
  if (name == "impact_map") return PlotKind::impact_map;
  if (name == "regime_map") return PlotKind::regime_map;
  if (name == "lyapunov") return PlotKind::lyapunov;
  if (name == "lyapunov_map") return PlotKind::lyapunov_map;
  return std::nullopt;
}

std::string sweep_result_csv(const SweepResult& result) {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "value,value2,start,direction,pellet,t,phi,dphi,phase,limiter,trusted,period,"
         "impacts_per_period,lyapunov\n";
  for (const SweepRun& run : result.runs)
    for (const SectionPoint& p : run.points)
      out << run.value << ',' << run.value2 << ',' << run.start << ',' << run.direction << ','
          << p.pellet << ',' << p.t << ',' << p.phi << ',' << p.dphi << ',' << p.phase << ','
          << p.limiter << ',' << (p.trusted ? 1 : 0) << ',' << run.period << ','
          << run.impacts_per_period << ',' << lyapunov_cell(run.lyapunov) << '\n';
  return out.str();
}

}  // namespace vibro
