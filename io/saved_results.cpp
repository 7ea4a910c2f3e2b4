#include "io/saved_results.h"

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "core/analysis/periodic_orbit.h"
#include "io/json_fields.h"

namespace vibro {
namespace {

using nlohmann::json;

// The array at `key` of `object`, of `size` entries when size >= 0.
const json& column(const json& object, const std::string& path, const std::string& key, long size) {
  const std::string field = path + "." + key;
  if (!object.is_object() || !object.contains(key) || !object[key].is_array())
    throw FieldException(field, "is required: a column (an array), as the sweep wrote it");
  const json& c = object[key];
  if (size >= 0 && static_cast<long>(c.size()) != size)
    throw FieldException(field, "has " + std::to_string(c.size()) + " entries, not " +
                                    std::to_string(size) + " as its table's other columns");
  return c;
}

// A number, null read as NaN (JSON holds no non-finite number).
double number_at(const json& c, std::size_t k, const std::string& field) {
  if (c[k].is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!c[k].is_number())
    throw FieldException(field, "entry " + std::to_string(k) + " is no number");
  return c[k].get<double>();
}

long integer_at(const json& c, std::size_t k, const std::string& field, long low, long high) {
  if (!c[k].is_number_integer() || c[k].get<long>() < low || c[k].get<long>() > high)
    throw FieldException(field, "entry " + std::to_string(k) + " must be an integer in " +
                                    std::to_string(low) + ".." + std::to_string(high));
  return c[k].get<long>();
}

bool boolean_at(const json& c, std::size_t k, const std::string& field) {
  if (!c[k].is_boolean())
    throw FieldException(field, "entry " + std::to_string(k) + " is no boolean");
  return c[k].get<bool>();
}

Termination termination_named(const json& name, const std::string& field) {
  for (Termination t :
       {Termination::completed, Termination::event_limit, Termination::step_limit,
        Termination::deadline, Termination::numerical_failure, Termination::cancelled})
    if (name.is_string() && name.get<std::string>() == termination_name(t)) return t;
  throw FieldException(field, "must name how a run ended (\"completed\", \"deadline\", ...)");
}

std::vector<SweepRun> read_runs(const json& runs) {
  const std::size_t n = column(runs, "runs", "value", -1).size();
  const long size = static_cast<long>(n);
  auto at = [&](const char* key) -> const json& { return column(runs, "runs", key, size); };
  std::vector<SweepRun> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    SweepRun& r = out[k];
    r.value = number_at(at("value"), k, "runs.value");
    r.value2 = number_at(at("value2"), k, "runs.value2");
    r.start = static_cast<int>(integer_at(at("start"), k, "runs.start", 0, 1L << 30));
    r.direction = static_cast<int>(integer_at(at("direction"), k, "runs.direction", -1, 1));
    r.period = static_cast<int>(integer_at(at("period"), k, "runs.period", 0, 1L << 30));
    r.impacts_per_period = number_at(at("impacts_per_period"), k, "runs.impacts_per_period");
    r.at_rest = boolean_at(at("at_rest"), k, "runs.at_rest");
    r.sticks = boolean_at(at("sticks"), k, "runs.sticks");
    r.trusted = boolean_at(at("trusted"), k, "runs.trusted");
    r.trusted_until = number_at(at("trusted_until"), k, "runs.trusted_until");
    r.error_estimate = number_at(at("error_estimate"), k, "runs.error_estimate");
    r.termination = termination_named(at("termination")[k], "runs.termination");
    if (at("message")[k].is_string()) r.message = at("message")[k].get<std::string>();
    if (const json& l = at("lyapunov"); !l[k].is_null())
      r.lyapunov = number_at(l, k, "runs.lyapunov");
  }
  return out;
}

// Each point to the run it names.
void read_points(const json& points, std::vector<SweepRun>& runs) {
  const std::size_t n = column(points, "points", "run", -1).size();
  const long size = static_cast<long>(n);
  auto at = [&](const char* key) -> const json& { return column(points, "points", key, size); };
  const long last_run = static_cast<long>(runs.size()) - 1;
  for (std::size_t k = 0; k < n; ++k) {
    const long run = integer_at(at("run"), k, "points.run", 0, last_run);
    runs[run].points.emplace_back(
        static_cast<int>(integer_at(at("pellet"), k, "points.pellet", 0, 32767)),
        number_at(at("t"), k, "points.t"), number_at(at("phi"), k, "points.phi"),
        number_at(at("dphi"), k, "points.dphi"), number_at(at("phase"), k, "points.phase"),
        static_cast<int>(integer_at(at("limiter"), k, "points.limiter", -1, 32767)),
        boolean_at(at("trusted"), k, "points.trusted"));
  }
}

const json& required(Fields& f, const std::string& key) {
  const json* v = f.value(key);
  if (!v) throw FieldException(f.path(key), "is required");
  return *v;
}

std::vector<PhasePoint> read_states(const json& list, const std::string& field) {
  if (!list.is_array()) throw FieldException(field, "must be a list of {\"phi\", \"dphi\"}");
  std::vector<PhasePoint> states;
  for (std::size_t k = 0; k < list.size(); ++k) {
    Fields f(list[k], field + "[" + std::to_string(k) + "]");
    states.push_back({f.required_number("phi"), f.required_number("dphi")});
  }
  return states;
}

// A basin sweep's attractor table and each run's attractor (runs.attractor, an id of the table
// or -1).
void read_attractors(const json& j, SweepResult& result) {
  const json& list = j["attractors"];
  if (!list.is_array()) throw FieldException("attractors", "must be a list of attractors");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string field = "attractors[" + std::to_string(k) + "]";
    Fields f(list[k], field);
    Attractor a;
    a.id = static_cast<int>(k);
    a.at_rest = f.boolean("at_rest", false);
    a.period = static_cast<int>(f.integer("period").value_or(0));
    a.impacts_per_period = f.number("impacts_per_period").value_or(0.0);
    a.cells = f.integer("cells").value_or(0);
    for (const PhasePoint& s : read_states(required(f, "section"), field + ".section"))
      a.section.emplace_back(s.phi, s.dphi);
    f.integer("id");
    f.done();
    result.attractors.push_back(std::move(a));
  }
  const json& ids = column(j["runs"], "runs", "attractor", static_cast<long>(result.runs.size()));
  const long last = static_cast<long>(result.attractors.size()) - 1;
  for (std::size_t k = 0; k < result.runs.size(); ++k)
    result.runs[k].attractor = static_cast<int>(integer_at(ids, k, "runs.attractor", -1, last));
  result.classified = true;
}

std::vector<std::complex<double>> read_multipliers(const json& list, const std::string& field) {
  if (!list.is_array()) throw FieldException(field, "must be a list of {\"re\", \"im\"}");
  std::vector<std::complex<double>> out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    Fields f(list[k], field + "[" + std::to_string(k) + "]");
    out.emplace_back(f.number("re").value_or(std::nan("")), f.number("im").value_or(0.0));
  }
  return out;
}

BifurcationKind bifurcation_named(const std::string& name, const std::string& field) {
  for (BifurcationKind k : {BifurcationKind::fold, BifurcationKind::period_doubling,
                            BifurcationKind::neimark_sacker, BifurcationKind::grazing})
    if (name == bifurcation_kind_name(k)) return k;
  throw FieldException(field,
                       "must be \"fold\", \"period_doubling\", \"neimark_sacker\" or "
                       "\"grazing\", got \"" +
                           name + "\"");
}

template <class Read>
auto caught(const Read& read) -> std::variant<decltype(read()), FieldError> {
  try {
    return read();
  } catch (const FieldException& e) {
    return FieldError{e.field, e.what()};
  } catch (const json::exception& e) {
    return FieldError{"result", std::string("is not a result as vibro writes it: ") + e.what()};
  }
}

}  // namespace

std::variant<SweepResult, FieldError> read_sweep_result(const json& j) {
  return caught([&] {
    if (!j.is_object() || !j.contains("runs") || !j.contains("points"))
      throw FieldException("result", "is no sweep result: it has no \"runs\" and \"points\"");
    SweepResult result;
    result.runs = read_runs(j["runs"]);
    read_points(j["points"], result.runs);
    if (j.contains("attractors")) read_attractors(j, result);
    return result;
  });
}

std::variant<OrbitBranch, FieldError> read_orbit_branch(const json& j, double multiplier_band) {
  return caught([&] {
    if (!j.is_object() || !j.contains("branch") || !j["branch"].is_array())
      throw FieldException("branch",
                           "is required: the continued branch, as `vibro orbit` wrote it");
    OrbitBranch branch;
    const json& points = j["branch"];
    for (std::size_t k = 0; k < points.size(); ++k) {
      const std::string field = "branch[" + std::to_string(k) + "]";
      Fields f(points[k], field);
      BranchPoint p;
      p.value = f.required_number("value");
      p.state = read_states(required(f, "state"), field + ".state");
      p.multipliers = read_multipliers(required(f, "multipliers"), field + ".multipliers");
      p.stable = f.boolean("stable", false);
      // A branch saved before "neutral" was written is judged by its multipliers.
      p.neutral = f.boolean("neutral", !p.stable && neutral_within(p.multipliers, multiplier_band));
      p.impacts_per_period = f.number("impacts_per_period").value_or(std::nan(""));
      branch.points.push_back(std::move(p));
    }
    const json& bifurcations = j.value("bifurcations", json::array());
    for (std::size_t k = 0; k < bifurcations.size(); ++k) {
      const std::string field = "bifurcations[" + std::to_string(k) + "]";
      Fields f(bifurcations[k], field);
      Bifurcation b;
      b.value = f.required_number("value");
      b.kind = bifurcation_named(f.string("kind", 32).value_or(""), field + ".kind");
      if (const json* state = f.value("state")) b.state = read_states(*state, field + ".state");
      if (const std::optional<std::string> side = f.string("approached_from", 32))
        b.approached_impacting = *side == "impacting";
      branch.bifurcations.push_back(std::move(b));
    }
    branch.reached = j.value("reached", false);
    branch.message = j.value("message", std::string());
    return branch;
  });
}

}  // namespace vibro
