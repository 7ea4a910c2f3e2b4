#include "tests/differential/conditioning.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tests/differential/scene_gen.h"

namespace vibro::differential {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Margin speed(double value, const char* what) {
  return {value, what, value < kGrazingSpeed, value < kRoundOffSpeed, true};
}

}  // namespace

Margin event_margin(const Model& model, const Event& e) {
  const double T0 = time_scale(model);
  const double gR = model.g / model.R;
  double M = 0.0, F = 0.0, dF = 0.0;
  for (int i : e.pellets) {
    const Forcing& f = model.pellets[i].force;
    M += model.pellets[i].m;
    F += f.at(e.t);
    dF += f.rate(e.t);
  }
  switch (e.kind) {
    case EventKind::limiter:
    case EventKind::chatter:
      return speed(std::abs(e.dphi_before[0]) * T0, "impact speed");
    case EventKind::collision:
      if (e.pellets.size() != 2) return {kInf, "cascade"};
      return speed(std::abs(e.dphi_before[0] - e.dphi_before[1]) * T0, "approach speed");
    case EventKind::reversal:
    case EventKind::stick: {
      const double a_free = F / (M * model.R) - gR * std::sin(e.phi);
      const double m = std::abs(std::abs(a_free) - stick_capacity(model, e.phi)) / gR;
      return {m, "stick margin", m < kStickMargin};
    }
    case EventKind::release: {
      if (dF == 0.0) return {kInf, "separation"};
      const double rate = std::abs(dF) * T0 / (M * model.g);
      return {rate, "release rate", rate < kReleaseRate};
    }
  }
  return {kInf, "?"};
}

double isolation(const Model& model, const RunResult& run, std::size_t index) {
  const double t = run.events[index].t;
  double nearest = kInf;
  for (const Event& e : run.events) {
    const double d = std::abs(e.t - t);
    if (d > 1e-12 * (1.0 + t)) nearest = std::min(nearest, d);
  }
  return nearest / time_scale(model);
}

std::string_view cause_name(Cause c) {
  switch (c) {
    case Cause::round_off_impact:
      return "round-off impact";
    case Cause::grazing:
      return "grazing";
    case Cause::stick_threshold:
      return "stick threshold";
    case Cause::tangent_release:
      return "tangent release";
    case Cause::simultaneous:
      return "near-simultaneous";
    case Cause::regrouped:
      return "regrouped contacts";
    case Cause::amplified:
      return "amplified";
    case Cause::unexplained:
      return "unexplained";
  }
  return "?";
}

Cause likely_cause(const MismatchContext& c) {
  if (c.a.round_off || c.b.round_off) return Cause::round_off_impact;
  for (const Margin* m : {&c.a, &c.b}) {
    if (!m->ill) continue;
    if (m->what == "stick margin") return Cause::stick_threshold;
    if (m->what == "release rate") return Cause::tangent_release;
    return Cause::grazing;
  }
  if (c.regrouped) return Cause::regrouped;
  if (c.isolation < kSimultaneous) return Cause::simultaneous;
  if (c.earlier_ill || (c.excess > 0.0 && c.excess * c.slowest <= 1.0)) return Cause::amplified;
  return Cause::unexplained;
}

}  // namespace vibro::differential
