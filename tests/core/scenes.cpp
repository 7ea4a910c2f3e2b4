#include "scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro::testing {

Model one_pellet(double alpha0, double phi0, double dphi0) {
  Model m;
  m.g = 9.81;
  m.R = 0.5;
  m.alpha0 = alpha0;
  Pellet p;
  p.m = 0.2;
  p.phi0 = phi0;
  p.dphi0 = dphi0;
  m.pellets.push_back(p);
  return m;
}

Scene preset(const std::string& name) {
  auto text = preset_json(name);
  EXPECT_TRUE(text.has_value()) << name;
  SceneOrError s = scene_from_text(text.value_or("{}"));
  if (auto* e = std::get_if<FieldError>(&s)) {
    ADD_FAILURE() << name << ": " << e->field << ": " << e->message;
    return Scene{};
  }
  return std::get<Scene>(s);
}

SimOptions recorded(const Model& model, double t_end, Method method, double rtol, double atol) {
  SimOptions o;
  o.t_end = t_end;
  o.method = method;
  o.rtol = rtol;
  o.atol = atol;
  o.record.assign(model.size(), true);
  return o;
}

std::string method_at(Method method, double rtol) {
  std::ostringstream s;
  s << method_name(method) << " at rtol " << rtol;
  return s.str();
}

std::vector<const Event*> events_of(const RunResult& run, EventKind kind) {
  std::vector<const Event*> out;
  for (const Event& e : run.events)
    if (e.kind == kind) out.push_back(&e);
  return out;
}

bool all_finite(const RunResult& run) {
  for (const Event& e : run.events) {
    if (!std::isfinite(e.t) || !std::isfinite(e.phi)) return false;
    for (double v : e.dphi_before)
      if (!std::isfinite(v)) return false;
    for (double v : e.dphi_after)
      if (!std::isfinite(v)) return false;
  }
  for (const PelletTrack& t : run.tracks)
    for (const Branch& b : t.branches)
      for (const Sample& s : b.samples)
        if (!std::isfinite(s.t) || !std::isfinite(s.phi) || !std::isfinite(s.dphi)) return false;
  for (const FinalState& f : run.summary.final)
    if (!std::isfinite(f.phi) || !std::isfinite(f.dphi)) return false;
  return std::isfinite(run.stats.error_estimate) && std::isfinite(run.stats.wall_ms);
}

}  // namespace vibro::testing
