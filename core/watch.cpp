#include "core/watch.h"

#include <cmath>
#include <limits>

#include "core/dynamics.h"

namespace vibro {

namespace {

double raw_value(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                 const Vec& y) {
  switch (w.kind) {
    case WatchKind::reversal:
      return bodies[w.body].s * y[dphi_index(w.pellet)];
    case WatchKind::limiter:
      return bodies[w.body].s * (w.target - y[phi_index(w.pellet)]);
    case WatchKind::gap:
      return y[phi_index(w.other)] - y[phi_index(w.pellet)] + w.target;
    case WatchKind::release: {
      const Body& b = bodies[w.body];
      const double phi = y[phi_index(w.pellet)];
      const double a = body_free_acceleration(model, b, t, phi);
      const double pull = b.mode == Mode::resting ? b.side * a : std::abs(a);
      return stick_capacity(model, phi) - pull;
    }
    case WatchKind::separation: {
      const Body& b = bodies[w.body];
      double F_behind = 0.0, m_behind = 0.0, F_ahead = 0.0, m_ahead = 0.0;
      for (int k = 0; k < static_cast<int>(b.members.size()); ++k) {
        const Pellet& p = model.pellets[b.members[k]];
        (k < w.split ? F_behind : F_ahead) += p.force.at(t);
        (k < w.split ? m_behind : m_ahead) += p.m;
      }
      // The part behind pushes the part ahead while it would accelerate faster on its own.
      return F_behind / m_behind - F_ahead / m_ahead;
    }
  }
  return 1.0;
}

}  // namespace

bool depends_on_time_alone(const Watch& w) {
  return w.kind == WatchKind::release || w.kind == WatchKind::separation;
}

TimeBounds time_bounds(const Watch& w, const Model& model, const std::vector<Body>& bodies,
                       double t) {
  const Body& b = bodies[w.body];
  // Per member: its force's rate and the bound of its second derivative, each over the mass
  // that shares it.
  double rate = 0.0, curvature = 0.0;
  if (w.kind == WatchKind::release) {
    const double MR = body_mass(model, b) * model.R;
    for (int i : b.members) {
      const Forcing& f = model.pellets[i].force;
      rate += f.rate(t) / MR;
      curvature += std::abs(f.F0) * f.Omega * f.Omega / MR;
    }
  } else {
    double m_behind = 0.0, m_ahead = 0.0;
    for (int k = 0; k < static_cast<int>(b.members.size()); ++k)
      (k < w.split ? m_behind : m_ahead) += model.pellets[b.members[k]].m;
    for (int k = 0; k < static_cast<int>(b.members.size()); ++k) {
      const Forcing& f = model.pellets[b.members[k]].force;
      const double m = k < w.split ? m_behind : -m_ahead;
      rate += f.rate(t) / m;
      curvature += std::abs(f.F0) * f.Omega * f.Omega / std::abs(m);
    }
  }
  return {std::abs(rate), curvature};
}

double evaluate(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                const Vec& y) {
  const double g = raw_value(w, model, bodies, t, y);
  if (!w.deflated) return g;
  return t > w.t0 ? (g - w.g0) / (t - w.t0) : w.rate0;
}

void deflate(Watch& w, const Model& model, const std::vector<Body>& bodies, double t0,
             const Vec& y0, double rate) {
  w.deflated = false;
  w.g0 = raw_value(w, model, bodies, t0, y0);
  w.t0 = t0;
  w.rate0 = rate;
  w.deflated = true;
}

bool next_limiter(const Model& model, const std::vector<bool>& armed, const Body& body,
                  double phi, int s, int& limiter, double& target) {
  bool found = false;
  for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
    if (!armed[l]) continue;
    bool acts = false;
    for (int i : body.members) acts = acts || model.limiters[l].acts_on(i);
    if (!acts) continue;
    const double theta = model.limiters[l].angle;
    // Candidates theta + 2πk near phi, each computed the same way as the angle an impact snaps
    // to, so a pellet that sits on the limiter never finds it again a hair ahead.
    const double n = std::floor((phi - theta) / kTwoPi);
    double x = s > 0 ? std::numeric_limits<double>::infinity()
                     : -std::numeric_limits<double>::infinity();
    for (double k = n - 1.0; k <= n + 2.0; k += 1.0) {
      const double c = theta + kTwoPi * k;
      if (s > 0 ? (c > phi && c < x) : (c < phi && c > x)) x = c;
    }
    if (!found || (s > 0 ? x < target : x > target)) {
      found = true;
      limiter = l;
      target = x;
    }
  }
  return found;
}

bool CrossingFinder::scan_between(const Watch& w, const Model& model,
                                  const std::vector<Body>& bodies, const Vec& y, double t_a,
                                  double g_a, double t_b, double& lo, double& hi, double& g_lo,
                                  double& g_hi) const {
  // Each step is the largest the bounds allow without a root; near a tangency the steps shrink
  // geometrically, and past it they grow again, so a few dozen steps cover any interval.
  constexpr int kMaxSteps = 1000;
  double t = t_a, g = g_a;
  for (int k = 0; k < kMaxSteps; ++k) {
    const TimeBounds b = time_bounds(w, model, bodies, t);
    const double root = std::sqrt(b.rate * b.rate + 2.0 * b.curvature * g);
    double step = b.rate + root > 0.0 ? 2.0 * g / (b.rate + root)
                                      : std::numeric_limits<double>::infinity();
    step = std::max(step, 4.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::abs(t)));
    const double next = t + step;
    if (!(next < t_b)) return false;
    const double g_next = evaluate(w, model, bodies, next, y);
    if (g_next <= 0.0) {
      lo = t;
      hi = next;
      g_lo = g;
      g_hi = g_next;
      return true;
    }
    t = next;
    g = g_next;
  }
  return false;  // a touch without a crossing, to round-off
}

void CrossingFinder::start(const std::vector<Watch>& watches, const Model& model,
                           const std::vector<Body>& bodies, double t0, const Vec& y0) {
  last_.resize(watches.size());
  armed_.assign(watches.size(), false);
  for (std::size_t w = 0; w < watches.size(); ++w) {
    last_[w] = evaluate(watches[w], model, bodies, t0, y0);
    armed_[w] = last_[w] > 0.0;
  }
}

}  // namespace vibro
