#include "tests/differential/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <vector>

namespace vibro::differential {
namespace {

bool same_identity(const Event& a, const Event& b) {
  return a.kind == b.kind && a.pellets == b.pellets && a.limiter == b.limiter;
}

bool finite_event(const Event& e) {
  bool ok = std::isfinite(e.t) && std::isfinite(e.phi);
  for (double v : e.dphi_before) ok = ok && std::isfinite(v);
  for (double v : e.dphi_after) ok = ok && std::isfinite(v);
  return ok;
}

std::string at_event(std::size_t k, const Event& e) {
  std::ostringstream s;
  s << "event " << k << " (" << event_name(e) << " at t=" << e.t << "): ";
  return s.str();
}

// Impact laws at one event; empty when it keeps them. `scale` is the largest speed involved,
// so round-off in the engine's arithmetic (a few ulps of it) passes.
std::optional<std::string> impact_violation(const Model& model, const Event& e) {
  double scale = 0.0;
  for (double v : e.dphi_before) scale = std::max(scale, std::abs(v));
  const double eps = 1e-12 * std::max(scale, 1e-300);
  if (e.kind == EventKind::limiter && e.impacts_resolved == 0) {
    const double k = model.limiters[e.limiter].k;
    if (std::abs(e.dphi_after[0] + k * e.dphi_before[0]) > eps)
      return "limiter impact does not leave with -k times its speed";
    if (std::abs(wrap_angle(e.phi - model.limiters[e.limiter].angle)) > 1e-9)
      return "limiter impact away from the limiter's angle";
  }
  if (e.kind == EventKind::collision && e.limiter < 0) {
    double p_before = 0.0, p_after = 0.0, p_scale = 0.0;
    for (std::size_t k = 0; k < e.pellets.size(); ++k) {
      const double m = model.pellets[e.pellets[k]].m;
      p_before += m * e.dphi_before[k];
      p_after += m * e.dphi_after[k];
      p_scale += m * std::abs(e.dphi_before[k]);
    }
    if (std::abs(p_after - p_before) > 1e-12 * std::max(p_scale, 1e-300))
      return "collision does not conserve momentum";
    if (e.pellets.size() == 2 && e.impacts_resolved == 0) {  // one pairwise Newton impact
      const double rel_before = e.dphi_before[1] - e.dphi_before[0];
      const double rel_after = e.dphi_after[1] - e.dphi_after[0];
      if (std::abs(rel_after + model.k_c * rel_before) > 4.0 * eps)
        return "collision does not follow Newton's restitution k_c";
    }
  }
  if (e.kind == EventKind::chatter) {
    for (double v : e.dphi_after)
      if (v != 0.0) return "chatter does not end at rest";
  }
  return std::nullopt;
}

// Pellets never pass each other: the gap from each pellet to the next around the circle, in
// the initial order, stays in [0, 2π] with the angles unwrapped.
std::optional<std::string> order_violation(const Model& model, const RunResult& run) {
  const int n = model.size();
  if (n < 2) return std::nullopt;
  auto place = [](double phi) {
    const double w = std::fmod(phi, kTwoPi);
    return w < 0.0 ? w + kTwoPi : w;
  };
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return place(model.pellets[i].phi0) < place(model.pellets[j].phi0);
  });
  for (int k = 0; k < n; ++k) {
    const int behind = order[k], ahead = order[(k + 1) % n];
    const double phi_b = model.pellets[behind].phi0, phi_a = model.pellets[ahead].phi0;
    double gap0 = place(phi_a) - place(phi_b);
    if (k == n - 1) gap0 += kTwoPi;
    const double offset = gap0 - (phi_a - phi_b);
    const double gap = run.summary.final[ahead].phi - run.summary.final[behind].phi + offset;
    const double slack = 1e-9 * (1.0 + std::abs(run.summary.final[ahead].phi));
    if (gap < -slack || gap > kTwoPi + slack) {
      std::ostringstream s;
      s << "pellet " << ahead << " and pellet " << behind << " passed each other (gap " << gap
        << " rad at the end)";
      return s.str();
    }
  }
  return std::nullopt;
}

// A pellet never passes a fixed limiter that acts on it: it ends inside the arc between the
// nearest such limiters below and above where it started (unwrapped), ends included. A pellet
// that starts on a limiter may lie on either side of it: it stays within a turn of it.
std::optional<std::string> limiter_violation(const Model& model, const RunResult& run) {
  for (int i = 0; i < model.size(); ++i) {
    const double phi0 = model.pellets[i].phi0;
    double below = -std::numeric_limits<double>::infinity();
    double above = std::numeric_limits<double>::infinity();
    for (const Limiter& l : model.limiters) {
      if (l.mobile || !l.acts_on(i)) continue;
      double d = std::fmod(phi0 - l.angle, kTwoPi);
      if (d < 0.0) d += kTwoPi;
      const double under = phi0 - d;  // the nearest angle ≤ phi0
      const bool on = std::min(d, kTwoPi - d) <= 1e-12 * (1.0 + std::abs(phi0));
      below = std::max(below, on ? phi0 - kTwoPi : under);
      above = std::min(above, on ? phi0 + kTwoPi : under + kTwoPi);
    }
    const double phi = run.summary.final[i].phi;
    const double slack = 1e-9 * (1.0 + std::abs(phi));
    if (phi < below - slack || phi > above + slack) {
      std::ostringstream s;
      s << "pellet " << i << " passed a fixed limiter that acts on it (it ends at " << phi
        << ", outside [" << below << ", " << above << "])";
      return s.str();
    }
  }
  return std::nullopt;
}

// An impact's time errs by the position's error over the approach speed w: a slow impact (a
// grazing one) is less well determined than a fast one by v/w, v = 1/T0 the speed scale.
double conditioning(const Event& e, double time_scale) {
  double w = 0.0;
  if (e.kind == EventKind::limiter && !e.dphi_before.empty()) {
    w = std::abs(e.dphi_before.front());
  } else if (e.kind == EventKind::collision && e.dphi_before.size() >= 2) {
    w = std::abs(e.dphi_before.front() - e.dphi_before.back());
  } else {
    return 1.0;
  }
  return std::max(1.0, 1.0 / (time_scale * w));
}

}  // namespace

std::string_view verdict_name(Verdict v) {
  switch (v) {
    case Verdict::agree:
      return "agree";
    case Verdict::sequence:
      return "sequence";
    case Verdict::time:
      return "time";
  }
  return "?";
}

std::string event_name(const Event& e) {
  std::ostringstream s;
  s << event_kind_name(e.kind) << " [";
  for (std::size_t k = 0; k < e.pellets.size(); ++k) s << (k ? "," : "") << e.pellets[k];
  s << "]";
  if (e.limiter >= 0) s << " L" << e.limiter;
  return s.str();
}

Comparison compare_runs(const RunResult& a, const RunResult& b, const TimeTolerance& tol,
                        double t_end) {
  Comparison c;
  std::vector<Event> bs = b.events;  // reordered below where near-simultaneous events swap
  const std::size_t n = std::min(a.events.size(), bs.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Event& ea = a.events[i];
    if (!same_identity(ea, bs[i])) {
      for (std::size_t j = i + 1; j < bs.size() && bs[j].t <= ea.t + tol.at(ea.t); ++j) {
        if (same_identity(ea, bs[j])) {
          std::rotate(bs.begin() + i, bs.begin() + j, bs.begin() + j + 1);
          break;
        }
      }
    }
    const Event& eb = bs[i];
    const double dt = std::abs(ea.t - eb.t);
    const double t = std::max(ea.t, eb.t);
    const double allowed = std::max(
        tol.at(t) * std::max(conditioning(ea, tol.time_scale), conditioning(eb, tol.time_scale)),
        tol.stated);
    if (!same_identity(ea, eb) || dt > allowed) {
      c.verdict = same_identity(ea, eb) ? Verdict::time : Verdict::sequence;
      c.index = i;
      c.a = ea;
      c.b = eb;
      c.dt = dt;
      c.tolerance = allowed;
      return c;
    }
    c.worst_ratio = std::max(c.worst_ratio, dt / allowed * TimeTolerance::kFactor);
  }
  // One run has more events: fine only where they lie within the tolerance of the end (the
  // end may be a run's trust horizon, where its own copy of the event lies, as late as the
  // error it states).
  const std::vector<Event>& longer = a.events.size() > n ? a.events : bs;
  if (longer.size() > n && longer[n].t < t_end - std::max(tol.at(t_end), tol.stated)) {
    c.verdict = Verdict::sequence;
    c.index = n;
    if (a.events.size() > n)
      c.a = longer[n];
    else
      c.b = longer[n];
    c.tolerance = tol.at(longer[n].t);
  }
  return c;
}

std::string describe(const Comparison& c, const std::string& name_a, const std::string& name_b) {
  std::ostringstream s;
  s << verdict_name(c.verdict) << " at event " << c.index << ": ";
  auto side = [&](const std::string& name, const std::optional<Event>& e) {
    s << name;
    if (e)
      s << " has " << event_name(*e) << " at t=" << e->t;
    else
      s << " has no event";
  };
  side(name_a, c.a);
  s << ", ";
  side(name_b, c.b);
  if (c.a && c.b) s << " (|dt| " << c.dt << ", tolerance " << c.tolerance << ")";
  return s.str();
}

bool stopped_by_budget(const RunResult& run) {
  const Termination t = run.stats.termination;
  return t == Termination::event_limit || t == Termination::step_limit ||
         t == Termination::deadline;
}

std::optional<std::string> physics_violation(const Model& model, const RunResult& run,
                                             double t_end) {
  if (run.stats.termination != Termination::completed)
    return "the run did not complete: " + run.stats.message;
  double t_prev = 0.0;
  for (std::size_t k = 0; k < run.events.size(); ++k) {
    const Event& e = run.events[k];
    if (e.dphi_before.size() != e.pellets.size() || e.dphi_after.size() != e.pellets.size())
      return at_event(k, e) + "velocities do not match its pellets";
    if (!finite_event(e)) return at_event(k, e) + "a number is not finite";
    if (e.t < t_prev) return at_event(k, e) + "out of time order";
    if (e.t > t_end * (1.0 + 1e-12)) return at_event(k, e) + "after t_end";
    t_prev = e.t;
    if (auto v = impact_violation(model, e)) return at_event(k, e) + *v;
  }
  if (static_cast<int>(run.summary.final.size()) != model.size())
    return std::string("not one final state per pellet");
  for (std::size_t i = 0; i < run.summary.final.size(); ++i) {
    const FinalState& f = run.summary.final[i];
    if (!std::isfinite(f.phi) || !std::isfinite(f.dphi))
      return "pellet " + std::to_string(i) + "'s final state is not finite";
    if (f.state == PelletState::resting_at_limiter && f.limiter >= 0 &&
        std::abs(wrap_angle(f.phi - model.limiters[f.limiter].angle)) > 1e-9)
      return "pellet " + std::to_string(i) + " rests at a limiter away from its angle";
  }
  // The energy balance and the exact first integral (Stats) hold to what the tolerance
  // allows, as event times do (TimeTolerance::kFactor·rtol), plus for the energy the error of
  // summing chatter in closed form (about 1e-8 of the energy scale) with a margin of ten.
  const double allowed = TimeTolerance::kFactor * run.stats.rtol;
  if (run.stats.energy_defect > allowed + 1e-7) {
    std::ostringstream s;
    s << "energy balance defect " << run.stats.energy_defect << " (allowed " << allowed + 1e-7
      << ")";
    return s.str();
  }
  if (run.stats.first_integral_residual > allowed) {
    std::ostringstream s;
    s << "first-integral residual " << run.stats.first_integral_residual << " (allowed " << allowed
      << ")";
    return s.str();
  }
  if (auto v = limiter_violation(model, run)) return v;
  return order_violation(model, run);
}

}  // namespace vibro::differential
