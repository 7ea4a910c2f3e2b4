#include "core/analysis/attractors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace vibro {
namespace {

// The pellet index of an initial-state path, "model.pellets[i].phi0" or ".dphi0"; false for
// any other path.
bool initial_state_field(const std::string& path) {
  const std::string head = "model.pellets[";
  if (!path.starts_with(head)) return false;
  const std::size_t close = path.find(']', head.size());
  if (close == std::string::npos || close == head.size()) return false;
  for (std::size_t k = head.size(); k < close; ++k)
    if (path[k] < '0' || path[k] > '9') return false;
  const std::string field = path.substr(close + 1);
  return field == ".phi0" || field == ".dphi0";
}

std::optional<FieldError> axis_not_initial(const SweepAxis& axis, const std::string& field) {
  if (initial_state_field(axis.parameter)) return std::nullopt;
  return FieldError{field, "\"" + axis.parameter +
                               "\" is not an initial-state field: \"classify\": \"attractor\" "
                               "sweeps initial states, model.pellets[i].phi0 or "
                               "model.pellets[i].dphi0"};
}

using Cycle = std::vector<std::pair<double, double>>;

// Whether two cycles of one period are the same motion: every state within the tolerance.
bool same_motion(const Cycle& a, const Cycle& b, double tol_phi, double tol_dphi) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (std::abs(std::remainder(a[k].first - b[k].first, kTwoPi)) > tol_phi ||
        std::abs(a[k].second - b[k].second) > tol_dphi)
      return false;
  return true;
}

}  // namespace

std::optional<FieldError> validate_attractor_sweep(const SweepSpec& spec) {
  if (!spec.classify_attractor) return std::nullopt;
  if (auto e = axis_not_initial(spec.axis, "sweep.parameter")) return e;
  if (spec.axis2)
    if (auto e = axis_not_initial(*spec.axis2, "sweep.parameter2.parameter")) return e;
  if (spec.section != SectionKind::stroboscopic)
    return FieldError{"sweep.section",
                      "must be \"stroboscopic\" with \"classify\": \"attractor\": attractors are "
                      "told apart by their stroboscopic section points"};
  if (spec.continuation != Continuation::none)
    return FieldError{"sweep.continuation",
                      "must be \"none\" with \"classify\": \"attractor\": each run starts from "
                      "its own swept initial state"};
  if (spec.initial_states != 1)
    return FieldError{"sweep.initial_states",
                      "must be 1 with \"classify\": \"attractor\": the swept fields are the "
                      "initial states"};
  return std::nullopt;
}

Cycle attractor_cycle(const SweepRun& run, int pellets) {
  const std::size_t n = static_cast<std::size_t>(std::max(pellets, 1));
  const std::size_t p = static_cast<std::size_t>(std::max(run.period, 0));
  if (p == 0 || run.points.size() < p * n) return {};
  // The last p stops, each a block of n points (one per pellet).
  std::vector<Cycle> stops(p);
  const std::size_t first = run.points.size() - p * n;
  for (std::size_t k = 0; k < p; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const SectionPoint& s = run.points[first + k * n + i];
      stops[k].emplace_back(wrap_angle(s.phi), s.dphi);
    }
  const std::size_t least =
      static_cast<std::size_t>(std::min_element(stops.begin(), stops.end()) - stops.begin());
  Cycle cycle;
  cycle.reserve(p * n);
  for (std::size_t k = 0; k < p; ++k) {
    const Cycle& s = stops[(least + k) % p];
    cycle.insert(cycle.end(), s.begin(), s.end());
  }
  return cycle;
}

AttractorTable::AttractorTable(const Model& model)
    // Settled runs of one motion agree to about 1e-5 of its extent (the period test); distinct
    // coexisting motions of a vibro-impact system differ by far more than 1e-3 rad or 1e-3 of
    // the model's speed scale.
    : pellets_(model.size()), tol_phi_(1e-3), tol_dphi_(1e-3 * speed_scale(model)) {}

int AttractorTable::add(const SweepRun& run) {
  if (run.rests) {
    if (rest_ < 0) {
      rest_ = static_cast<int>(classes_.size());
      classes_.push_back(Class{true, 1, {}, 0.0, 0});
    }
    ++classes_[rest_].cells;
    return rest_;
  }
  Cycle cycle = attractor_cycle(run, pellets_);
  if (cycle.empty()) return -1;
  auto match = std::find_if(classes_.begin(), classes_.end(), [&](const Class& c) {
    return !c.rest && c.period == run.period && same_motion(c.cycle, cycle, tol_phi_, tol_dphi_);
  });
  if (match == classes_.end())
    match = classes_.insert(classes_.end(),
                            Class{false, run.period, std::move(cycle), run.impacts_per_period, 0});
  ++match->cells;
  return static_cast<int>(match - classes_.begin());
}

std::vector<Attractor> AttractorTable::finish(std::vector<int>& id_of) const {
  std::vector<int> order(classes_.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Class& x = classes_[a];
    const Class& y = classes_[b];
    const bool x_moves = !x.rest, y_moves = !y.rest;
    return std::tie(x_moves, x.period, x.cycle) < std::tie(y_moves, y.period, y.cycle);
  });
  id_of.assign(classes_.size(), -1);
  std::vector<Attractor> attractors;
  for (std::size_t id = 0; id < order.size(); ++id) {
    const Class& c = classes_[order[id]];
    id_of[order[id]] = static_cast<int>(id);
    attractors.push_back(
        {static_cast<int>(id), c.rest, c.period, c.impacts_per_period, c.cycle, c.cells});
  }
  return attractors;
}

void classify_attractors(const Model& model, SweepResult& result) {
  AttractorTable table(model);
  std::vector<int> class_of;
  class_of.reserve(result.runs.size());
  for (const SweepRun& run : result.runs) class_of.push_back(table.add(run));
  std::vector<int> id_of;
  result.attractors = table.finish(id_of);
  for (std::size_t r = 0; r < result.runs.size(); ++r)
    result.runs[r].attractor = class_of[r] < 0 ? -1 : id_of[class_of[r]];
  result.classified = true;
}

}  // namespace vibro
