#include "core/events/watch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/dynamics.h"

namespace vibro {

namespace {

// The forces on some members of a body: their sum, its rate, and a bound of its second derivative.
struct PartForces {
  double F = 0.0, rate = 0.0, curvature = 0.0, m = 0.0;
  double mc = 0.0;  // Σ m_i c_i, kg/s
};

PartForces part_forces(const Model& model, const Body& b, int from, int to, double t) {
  PartForces p;
  for (int k = from; k < to; ++k) {
    const Pellet& pellet = model.pellets[b.members[k]];
    p.F += pellet.force.at(t);
    p.rate += pellet.force.rate(t);
    p.curvature += std::abs(pellet.force.F0) * pellet.force.Omega * pellet.force.Omega;
    p.m += pellet.m;
    p.mc += pellet.m * pellet.c;
  }
  return p;
}

// The parts of a body on either side of a separation watch's cut.
struct Parts {
  PartForces behind, ahead;
};

Parts parts(const Model& model, const Body& b, int split, double t) {
  const int n = static_cast<int>(b.members.size());
  return {part_forces(model, b, 0, split, t), part_forces(model, b, split, n, t)};
}

// A held body (stuck, or resting on a limiter) comes apart where a part at its end is pulled off
// harder than friction holds it: the part ahead forward, the part behind backward; against a
// limiter only the part away from it. The margins, in rad/s²: pulled off when one reaches 0.
struct HeldMargins {
  double ahead = std::numeric_limits<double>::infinity();
  double behind = std::numeric_limits<double>::infinity();
};

HeldMargins held_margins(const Model& model, const Body& b, const Parts& p, double phi) {
  const double c = stick_capacity(model, phi);
  const double gravity = model.g / model.R * std::sin(phi);
  const double a_ahead = p.ahead.F / (p.ahead.m * model.R) - gravity;
  const double a_behind = p.behind.F / (p.behind.m * model.R) - gravity;
  HeldMargins m;
  if (!(b.mode == Mode::resting && b.side < 0)) m.ahead = c - a_ahead;
  if (!(b.mode == Mode::resting && b.side > 0)) m.behind = c + a_behind;
  return m;
}

}  // namespace

double raw_value(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                 const Vec& y) {
  switch (w.kind) {
    case WatchKind::reversal:
      return bodies[w.body].s * y[dphi_index(w.pellet)];
    case WatchKind::limiter:
      return w.side * (w.target - y[phi_index(w.pellet)]);
    case WatchKind::gap:
      return y[phi_index(w.other)] - y[phi_index(w.pellet)] + w.target;
    case WatchKind::release: {
      const Body& b = bodies[w.body];
      const double phi = y[phi_index(w.pellet)];
      const double a = body_free_acceleration(model, b, t, phi);
      const double pull = b.mode == Mode::resting ? b.side * a : std::abs(a);
      return stick_capacity(model, phi) + w.target - pull;
    }
    case WatchKind::normal:
      return w.target * normal_per_mass(model, y[phi_index(w.pellet)], y[dphi_index(w.pellet)]);
    case WatchKind::separation: {
      const Body& b = bodies[w.body];
      const Parts p = parts(model, b, w.split, t);
      if (b.mode != Mode::sliding) {
        const HeldMargins m = held_margins(model, b, p, y[phi_index(w.pellet)]);
        return std::min(m.ahead, m.behind);
      }
      // Sliding, friction and gravity per unit mass are the same for every part: the part
      // behind pushes the part ahead while its force per mass, less its dampers', is larger.
      return p.behind.F / p.behind.m - p.ahead.F / p.ahead.m -
             model.R * y[dphi_index(w.pellet)] *
                 (p.behind.mc / p.behind.m - p.ahead.mc / p.ahead.m);
    }
  }
  return 1.0;
}

double Closing::time_to_zero() const {
  if (!(value >= 0.0) || (value == 0.0 && !(rate > 0.0))) return 0.0;  // on or past its root
  if (curvature < 0.0)  // the positive root of value + rate·τ + curvature·τ²/2
    return (rate + std::sqrt(rate * rate - 2.0 * curvature * value)) / -curvature;
  return rate < 0.0 ? value / -rate : std::numeric_limits<double>::infinity();
}

namespace {

// The acceleration of the body pellet i belongs to: sliding, under the friction law; held, 0.
double acceleration_of(const Model& model, const SlidingLaw& law, const Body& b, double t,
                       const Vec& y) {
  if (b.mode != Mode::sliding) return 0.0;
  const double phi = y[phi_index(b.leader())];
  return law.acceleration(body_load(model, b, t), std::cos(phi), std::sin(phi),
                          y[dphi_index(b.leader())], b.s);
}

}  // namespace

const Body& body_of(const std::vector<Body>& bodies, int pellet) {
  for (const Body& b : bodies)
    if (std::find(b.members.begin(), b.members.end(), pellet) != b.members.end()) return b;
  return bodies.front();  // every pellet is in a body
}

Closing closing(const Watch& w, const Model& model, const SlidingLaw& law,
                const std::vector<Body>& bodies, double t, const Vec& y, bool with_curvature) {
  Closing c;
  c.value = raw_value(w, model, bodies, t, y) - (w.deflation != 0 ? w.g0 : 0.0);
  switch (w.kind) {
    case WatchKind::gap:
      c.rate = y[dphi_index(w.other)] - y[dphi_index(w.pellet)];
      if (with_curvature)
        c.curvature = acceleration_of(model, law, body_of(bodies, w.other), t, y) -
                      acceleration_of(model, law, body_of(bodies, w.pellet), t, y);
      break;
    case WatchKind::limiter:
      c.rate = -w.side * y[dphi_index(w.pellet)];
      if (with_curvature) c.curvature = -w.side * acceleration_of(model, law, bodies[w.body], t, y);
      break;
    case WatchKind::reversal:
      c.rate = bodies[w.body].s * acceleration_of(model, law, bodies[w.body], t, y);
      break;
    default:
      break;
  }
  return c;
}

bool depends_on_time_alone(const Watch& w, const Model& model, const std::vector<Body>& bodies) {
  if (w.kind == WatchKind::release) return true;
  if (w.kind != WatchKind::separation) return false;
  const Body& b = bodies[w.body];
  if (b.mode != Mode::sliding) return true;
  const Parts p = parts(model, b, w.split, 0.0);
  return p.behind.mc / p.behind.m == p.ahead.mc / p.ahead.m;
}

TimeBounds time_bounds(const Watch& w, const Model& model, const std::vector<Body>& bodies,
                       double t) {
  const Body& b = bodies[w.body];
  if (w.kind == WatchKind::release) {
    const PartForces f = part_forces(model, b, 0, static_cast<int>(b.members.size()), t);
    const double MR = f.m * model.R;
    return {std::abs(f.rate) / MR, f.curvature / MR};
  }
  const Parts p = parts(model, b, w.split, t);
  if (b.mode == Mode::sliding) {
    return {std::abs(p.behind.rate / p.behind.m - p.ahead.rate / p.ahead.m),
            p.behind.curvature / p.behind.m + p.ahead.curvature / p.ahead.m};
  }
  // A minimum of the two margins is bounded by the larger of their bounds.
  const double R = model.R;
  return {std::max(std::abs(p.ahead.rate) / (p.ahead.m * R),
                   std::abs(p.behind.rate) / (p.behind.m * R)),
          std::max(p.ahead.curvature / (p.ahead.m * R), p.behind.curvature / (p.behind.m * R))};
}

int pulled_off(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
               const Vec& y) {
  const Body& b = bodies[w.body];
  if (w.kind != WatchKind::separation || b.mode == Mode::sliding) return 0;
  const HeldMargins m = held_margins(model, b, parts(model, b, w.split, t), y[phi_index(w.pellet)]);
  return m.ahead <= m.behind ? 1 : -1;
}

int release_direction(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                      const Vec& y) {
  const Body& b = bodies[w.body];
  if (b.mode == Mode::resting) return b.side;
  const double phi = y[phi_index(w.pellet)];
  const double a = body_free_acceleration(model, b, t, phi);
  // At the root |a_free| = capacity: its sign is firm unless the capacity is nil (no static
  // friction), where a_free crosses zero and only its rate says which way.
  if (std::abs(a) >= 0.5 * stick_capacity(model, phi) && stick_capacity(model, phi) > 0.0)
    return a < 0.0 ? -1 : 1;
  const PartForces f = part_forces(model, b, 0, static_cast<int>(b.members.size()), t);
  return f.rate < 0.0 ? -1 : 1;
}

double evaluate(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                const Vec& y) {
  const double g = raw_value(w, model, bodies, t, y);
  if (w.deflation == 0) return g;
  if (!(t > w.t0)) return w.start;
  const double dt = t - w.t0;
  return w.deflation == 1 ? (g - w.g0) / dt : (g - w.g0) / (dt * dt);
}

void deflate(Watch& w, const Model& model, const std::vector<Body>& bodies, double t0,
             const Vec& y0, double rate, double accel) {
  w.g0 = raw_value(w, model, bodies, t0, y0);
  w.t0 = t0;
  w.deflation = rate != 0.0 ? 1 : 2;
  w.start = rate != 0.0 ? rate : 0.5 * accel;
}

namespace {

// The angles theta + 2πk about phi, each computed the same way as the angle an impact snaps to,
// so a pellet that sits on the limiter never finds it again a hair ahead.
template <class F>
void for_each_limiter_angle(double theta, double phi, F f) {
  // An integer counter: past 2^53 turns, k + 1.0 == k and a floating-point loop never ends.
  const double n = std::floor((phi - theta) / kTwoPi);
  for (int j = -1; j <= 2; ++j) f(theta + kTwoPi * (n + j));
}

}  // namespace

bool on_limiter_angle(double theta, double phi, double near) {
  bool on = false;
  // c − phi is exact for close values (Sterbenz), so this is the one test every caller shares.
  for_each_limiter_angle(theta, phi, [&](double c) { on = on || std::abs(c - phi) <= near; });
  return on;
}

bool next_limiter(const Model& model, const std::vector<bool>& armed, const Body& body, double phi,
                  int s, double from, int& limiter, double& target) {
  // A limiter the body sits on, within round-off (from = near), is behind it: any impact on it
  // was resolved at the instant the body got there.
  bool found = false;
  for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
    if (!armed[l]) continue;
    bool acts = false;
    for (int i : body.members) acts = acts || model.limiters[l].acts_on(i);
    if (!acts) continue;
    double x =
        s > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for_each_limiter_angle(model.limiters[l].angle, phi, [&](double c) {
      if (s * (c - phi) > from && (s > 0 ? c < x : c > x)) x = c;
    });
    if (!found || (s > 0 ? x < target : x > target)) {
      found = true;
      limiter = l;
      target = x;
    }
  }
  return found;
}

std::optional<LinearForm> linear_form(const Watch& w, const std::vector<Body>& bodies) {
  switch (w.kind) {
    case WatchKind::reversal:
      return LinearForm{1, {dphi_index(w.pellet), 0}, {double(bodies[w.body].s), 0.0}, 0.0};
    case WatchKind::limiter: {
      const double s = w.side;
      return LinearForm{1, {phi_index(w.pellet), 0}, {-s, 0.0}, s * w.target};
    }
    case WatchKind::gap:
      return LinearForm{2, {phi_index(w.other), phi_index(w.pellet)}, {1.0, -1.0}, w.target};
    default:
      return std::nullopt;
  }
}

}  // namespace vibro
