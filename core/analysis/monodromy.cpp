#include "core/analysis/monodromy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "core/integrators/stepper.h"
#include "core/model/dynamics.h"
#include "core/model/motion.h"

namespace vibro {
namespace {

int angle_row(int pellet) { return 2 * pellet; }
int speed_row(int pellet) { return 2 * pellet + 1; }

Vec full_state(const std::vector<double>& y) {
  return Eigen::Map<const Vec>(y.data(), static_cast<Eigen::Index>(y.size()));
}

// The bodies' dynamics with the normal sides an interval had (empty: as the state gives them).
SegmentDynamics dynamics_of(const Model& model, const std::vector<Body>& bodies,
                            const std::vector<int>& sides, const Vec& y) {
  SegmentDynamics d(model, bodies, y);
  for (std::size_t b = 0; b < sides.size(); ++b) d.set_normal_side(static_cast<int>(b), sides[b]);
  return d;
}

// The rate of (phi, dphi) of every pellet.
Vec reduced_rate(const SegmentDynamics& d, int pellets, double t, const Vec& y) {
  Vec full(3 * pellets), out(2 * pellets);
  d.rhs(t, y, full);
  for (int i = 0; i < pellets; ++i) {
    out[angle_row(i)] = full[phi_index(i)];
    out[speed_row(i)] = full[dphi_index(i)];
  }
  return out;
}

// The variational equations of one interval: the motion (3 components per pellet) followed by
// perturbations of (phi, dphi), a 2N × m matrix Φ column by column, with Φ' = (∂f/∂y) Φ (m = 2N
// for the transition matrix, 1 for one perturbation). The work components do not act back on the
// motion, so they are left out of Φ.
class Variational final : public OdeSystem {
 public:
  Variational(const SegmentDynamics& dynamics, int pellets, int columns)
      : d_(dynamics),
        n_(pellets),
        m_(columns),
        full_(3 * pellets),
        rate_(3 * pellets),
        reduced_(2 * pellets, 2 * pellets) {}
  int dimension() const override { return 3 * n_ + 2 * n_ * m_; }
  void rhs(double t, const Vec& z, Vec& dzdt) const override {
    full_ = z.head(3 * n_);
    d_.rhs_and_motion_jacobian(t, full_, rate_, reduced_);
    dzdt.head(3 * n_) = rate_;
    Eigen::Map<const Mat> phi(z.data() + 3 * n_, 2 * n_, m_);
    Eigen::Map<Mat> dphi(dzdt.data() + 3 * n_, 2 * n_, m_);
    dphi.noalias() = reduced_ * phi;
  }
  // Only implicit methods ask for it, and the transitions are integrated explicitly: central
  // differences of rhs serve.
  void jacobian(double t, const Vec& z, Mat& dfdz, Vec& dfdt) const override {
    Vec zp = z, zm = z, fp(z.size()), fm(z.size());
    for (Eigen::Index k = 0; k < z.size(); ++k) {
      const double h = 1e-7 * (1.0 + std::abs(z[k]));
      zp[k] = z[k] + h;
      zm[k] = z[k] - h;
      rhs(t, zp, fp);
      rhs(t, zm, fm);
      dfdz.col(k) = (fp - fm) / (2.0 * h);
      zp[k] = zm[k] = z[k];
    }
    const double h = 1e-7 * (1.0 + std::abs(t));
    rhs(t + h, z, fp);
    rhs(t - h, z, fm);
    dfdt = (fp - fm) / (2.0 * h);
  }

 private:
  const SegmentDynamics& d_;
  const int n_, m_;
  mutable Vec full_, rate_;
  mutable Mat reduced_;
};

const Body* body_of(const std::vector<Body>& bodies, int pellet) {
  for (const Body& b : bodies)
    for (int i : b.members)
      if (i == pellet) return &b;
  return nullptr;
}

// A saltation's event: the surface h(y, t) = 0 it lies on (its gradient in the reduced state and
// its rate in time) and the reset G it applies there, acting on these pellets only.
struct Crossed {
  Vec grad;
  double h_t = 0.0;
  Mat reset;
  std::vector<int> pellets;
};

// The release threshold of a stuck pellet, mu_s·(g/R)·|cos phi| − |a_free(t, phi)|.
void release_surface(const Model& model, int i, double t, double phi, Crossed& c) {
  const double gR = model.g / model.R;
  const Forcing& f = model.pellets[i].force;
  const double a = free_acceleration(model, i, t, phi);
  const double sa = a >= 0.0 ? 1.0 : -1.0;
  const double sc = std::cos(phi) >= 0.0 ? 1.0 : -1.0;
  c.grad[angle_row(i)] = -model.mu_static() * gR * std::sin(phi) * sc + sa * gR * std::cos(phi);
  c.h_t = -sa * f.rate(t) / (model.pellets[i].m * model.R);
}

// The surface and reset of one event of an instant; none where it moves nothing (a release
// from rest on a limiter, whose place, and so whose time, is fixed).
std::optional<Crossed> crossed_by(const Model& model, const PathSegment& segment, const Event& e,
                                  const Vec& y_before) {
  const int n = model.size();
  Crossed c{Vec::Zero(2 * n), 0.0, Mat::Identity(2 * n, 2 * n), e.pellets};
  const int i = e.pellets.front();
  switch (e.kind) {
    case EventKind::limiter:
      c.grad[angle_row(i)] = 1.0;
      c.reset(speed_row(i), speed_row(i)) = -model.limiters[e.limiter].k;
      break;
    case EventKind::collision: {
      const int j = e.pellets[1];
      const double mi = model.pellets[i].m, mj = model.pellets[j].m, k = model.k_c;
      c.grad[angle_row(j)] = 1.0;
      c.grad[angle_row(i)] = -1.0;
      c.reset(speed_row(i), speed_row(i)) = (mi - k * mj) / (mi + mj);
      c.reset(speed_row(i), speed_row(j)) = mj * (1.0 + k) / (mi + mj);
      c.reset(speed_row(j), speed_row(j)) = (mj - k * mi) / (mi + mj);
      c.reset(speed_row(j), speed_row(i)) = mi * (1.0 + k) / (mi + mj);
      break;
    }
    case EventKind::reversal:
    case EventKind::stick:
      c.grad[speed_row(i)] = 1.0;
      break;
    case EventKind::release: {
      const Body* held = body_of(segment.bodies_before, i);
      if (held && held->mode == Mode::resting) return std::nullopt;
      release_surface(model, i, segment.t, y_before[phi_index(i)], c);
      break;
    }
    case EventKind::chatter:
      break;
  }
  return c;
}

// S_e = G + (f⁺ − G f⁻) ∇hᵀ / (∇h·f⁻ + h_t) on the event's pellets' rows, identity elsewhere.
Mat event_saltation(const Crossed& c, const Vec& f_before, const Vec& f_after, double approach) {
  const Vec jump = f_after - c.reset * f_before;
  Mat Se = Mat::Identity(f_before.size(), f_before.size());
  for (int p : c.pellets)
    for (int r : {angle_row(p), speed_row(p)})
      Se.row(r) = c.reset.row(r) + jump[r] / approach * c.grad.transpose();
  return Se;
}

// What the saltations do not cover at this instant, in words; empty where they cover it all:
// pellets moving together, or a pellet with several events at once.
std::string uncovered(const PathSegment& segment) {
  for (const auto* bodies : {&segment.bodies_before, &segment.bodies})
    for (const Body& b : *bodies)
      if (b.members.size() > 1)
        return "pellets moving together (at t = " + std::to_string(segment.t) + " s)";
  // An instant lists a few events: each pellet is looked for in the events before its own.
  const std::vector<Event>& events = segment.events;
  auto listed_before = [&](std::size_t k, int i) {
    return std::any_of(events.begin(), events.begin() + static_cast<std::ptrdiff_t>(k),
                       [&](const Event& e) {
                         return e.kind != EventKind::chatter &&
                                std::find(e.pellets.begin(), e.pellets.end(), i) != e.pellets.end();
                       });
  };
  for (std::size_t k = 0; k < events.size(); ++k) {
    if (events[k].kind == EventKind::chatter) continue;
    for (std::size_t j = 0; j < events[k].pellets.size(); ++j) {
      const int i = events[k].pellets[j];
      const auto rest = events[k].pellets.begin() + static_cast<std::ptrdiff_t>(j);
      if (listed_before(k, i) || std::find(events[k].pellets.begin(), rest, i) != rest)
        return "several events of pellet " + std::to_string(i + 1) +
               " at one instant (t = " + std::to_string(segment.t) + " s)";
    }
  }
  return {};
}

// Held pellets: a stuck one keeps dphi = 0 and a resting one its place on the limiter, whatever
// the perturbation that brought them there.
void hold_rows(const std::vector<Body>& bodies, Mat& S) {
  for (const Body& b : bodies) {
    if (b.mode == Mode::sliding) continue;
    const int i = b.leader();
    S.row(speed_row(i)).setZero();
    if (b.mode == Mode::resting) S.row(angle_row(i)).setZero();
  }
}

}  // namespace

PathJacobian instant_saltation(const Model& model, const PathSegment& segment,
                               const std::vector<int>& sides_before) {
  const int n = model.size();
  PathJacobian out;
  out.unsupported = uncovered(segment);
  if (!out.unsupported.empty()) return out;
  const Vec y_before = full_state(segment.y_before), y_after = full_state(segment.y);
  const Vec f_before = reduced_rate(
      dynamics_of(model, segment.bodies_before, sides_before, y_before), n, segment.t, y_before);
  const Vec f_after = reduced_rate(
      dynamics_of(model, segment.bodies, segment.normal_sides, y_after), n, segment.t, y_after);
  Mat S = Mat::Identity(2 * n, 2 * n);
  out.time_row = Vec::Zero(2 * n);
  bool timed = false;  // the instant's time is its first crossing's
  for (const Event& e : segment.events) {
    // A chatter sums the impacts after the one listed with it: the pellet ends at rest, which
    // hold_rows gives.
    if (e.kind == EventKind::chatter) continue;
    const std::optional<Crossed> c = crossed_by(model, segment, e, y_before);
    if (!c) continue;
    const double approach = c->grad.dot(f_before) + c->h_t;
    if (!timed) out.time_row = -c->grad / approach;  // h(y + δy, t + δt) = 0 to first order
    timed = true;
    S = event_saltation(*c, f_before, f_after, approach) * S;
  }
  hold_rows(segment.bodies, S);
  out.matrix = std::move(S);
  return out;
}

namespace {

// Φ·start over the motion interval a segment opens (start: 2N × m), integrated by `stepper`:
// started afresh, or going on with the step size it last took.
PathJacobian carried_over_interval(const Model& model, const PathSegment& segment, const Mat& start,
                                   Stepper& stepper, bool afresh) {
  const int n = model.size();
  const auto m = static_cast<int>(start.cols());
  PathJacobian out;
  out.matrix = start;
  if (!(segment.t_end > segment.t)) return out;
  const Vec y = full_state(segment.y);
  const SegmentDynamics d = dynamics_of(model, segment.bodies, segment.normal_sides, y);
  const Variational sys(d, n, m);
  Vec z(sys.dimension());
  z.head(3 * n) = y;
  Eigen::Map<Mat>(z.data() + 3 * n, 2 * n, m) = start;
  if (afresh)
    stepper.start(sys, segment.t, z);
  else
    stepper.continue_smoothly(sys, segment.t, z);
  while (stepper.t() < segment.t_end) {
    if (stepper.step(segment.t_end) != StepStatus::ok) {
      out.unsupported =
          "the variational equations failed to integrate at t = " + std::to_string(stepper.t()) +
          " s";
      return out;
    }
  }
  out.matrix = Eigen::Map<const Mat>(stepper.y().data() + 3 * n, 2 * n, m);
  return out;
}

}  // namespace

PathJacobian interval_transition(const Model& model, const PathSegment& segment, double rtol) {
  const int n = model.size();
  const std::unique_ptr<Stepper> stepper =
      make_stepper(Method::dop853, StepperOptions{rtol, 1e-3 * rtol, longest_step(model)});
  return carried_over_interval(model, segment, Mat::Identity(2 * n, 2 * n), *stepper, true);
}

PathJacobian segment_jacobian(const Model& model, const std::vector<PathSegment>& path,
                              std::size_t k, double rtol) {
  PathJacobian S =
      instant_saltation(model, path[k], k == 0 ? std::vector<int>{} : path[k - 1].normal_sides);
  if (!S.unsupported.empty()) return S;
  PathJacobian F = interval_transition(model, path[k], rtol);
  if (!F.unsupported.empty()) return F;
  F.matrix = F.matrix * S.matrix;
  return F;
}

PathJacobian path_jacobian(const Model& model, const std::vector<PathSegment>& path, double rtol,
                           const Deadline& deadline) {
  const int n = model.size();
  PathJacobian out;
  Mat M = Mat::Identity(2 * n, 2 * n);
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (deadline.passed()) {
      out.unsupported = "the deadline (passed at segment " + std::to_string(k) + " of " +
                        std::to_string(path.size()) + ")";
      out.out_of_time = true;
      return out;
    }
    const PathJacobian step = segment_jacobian(model, path, k, rtol);
    if (!step.unsupported.empty()) return step;
    M = step.matrix * M;
  }
  out.matrix = std::move(M);
  return out;
}

InstantShifts instant_shifts(const Model& model, const std::vector<PathSegment>& path,
                             const Mat& deltas, double rtol, double budget_ms) {
  const auto started = std::chrono::steady_clock::now();
  InstantShifts out;
  out.dt.resize(static_cast<Eigen::Index>(path.size()), deltas.cols());
  Mat v = deltas;
  // One stepper over the whole path, each interval begun with the step size the last one took
  // (the intervals of a chain of impacts are short, and a first-step guess for each cost more
  // than their steps), and steps up to two radians of a swing or a forcing: the shifts are wanted
  // to a few percent, and kept to them (against central differences of runs, and of shadows
  // started with and without their 64 ulps) at a quarter less cost than at one radian. `auto`,
  // for stiff friction: DOPRI5 took the stiff-friction preset's shifts at 3.5 times its run.
  const std::unique_ptr<Stepper> stepper =
      make_stepper(Method::automatic, StepperOptions{rtol, 1e-3 * rtol, 2.0 * longest_step(model)});
  auto unsupported = [&](const std::string& why) {
    out.unsupported = why;
    out.dt.resize(0, deltas.cols());
    return out;
  };
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count() > budget_ms) {
      out.dt.conservativeResize(static_cast<Eigen::Index>(k), deltas.cols());
      return out;
    }
    const PathJacobian S =
        instant_saltation(model, path[k], k == 0 ? std::vector<int>{} : path[k - 1].normal_sides);
    if (!S.unsupported.empty()) return unsupported(S.unsupported);
    out.dt.row(static_cast<Eigen::Index>(k)) = S.time_row.transpose() * v;
    if (k + 1 == path.size()) break;  // no instant after the last interval
    const PathJacobian F = carried_over_interval(model, path[k], S.matrix * v, *stepper, k == 0);
    if (!F.unsupported.empty()) return unsupported(F.unsupported);
    v = F.matrix;
  }
  return out;
}

}  // namespace vibro
