#include "core/analysis/orbit_continuation.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

#include "core/analysis/checked_run.h"
#include "core/analysis/grazing_orbit.h"
#include "core/model/parameter.h"

namespace vibro {
namespace {

// The parameter's unit in the continuation's scaled unknowns, signed toward `to`: the span
// to − p0, or the value's own size max(|p0|, 1) where the span is larger. Scaled by a far `to`'s
// span, the smallest step (kStepMin of the unit) and the parameter's difference step (1e-6 of it)
// would be far larger than the value: the branch could not take its first step. The span only
// bounds where the walk ends, at the scaled value span/unit (1 where `to` is near).
double parameter_unit(double p0, double span) {
  return std::copysign(std::min(std::abs(span), std::max(std::abs(p0), 1.0)), span);
}

// The largest half-range of a pellet's angle over a return of the motion: its state on the
// section and its events (rad).
double half_swing(const PeriodicOrbit& motion) {
  double swing = 0.0;
  for (std::size_t i = 0; i < motion.state.size(); ++i) {
    double lo = motion.state[i].phi, hi = lo;
    for (const Event& e : motion.events)
      if (!e.pellets.empty() && e.pellets[0] == static_cast<int>(i))
        lo = std::min(lo, e.phi), hi = std::max(hi, e.phi);
    swing = std::max(swing, 0.5 * (hi - lo));
  }
  return swing;
}

// The state's unit in the continuation's scaled unknowns and its thresholds (rad; speeds times
// sqrt(R/g)): twenty times the start motion's half-swing, fixed for the whole branch, 1 rad at most
// (motions of a half-swing of 0.05 rad or more are measured in rad) and 1e-3 rad at least (a motion
// at or near rest gives no size to go by). Measured so, a smaller motion is followed as one of a
// half-swing of 0.05 rad, its scaled problem the same up to the pendulum's nonlinearity: in rad,
// the angles of a milliradian's swing weigh nothing in the arclength against the parameter, and a
// step crosses a fold's turn (a third of the swing at a nearly fixed parameter) unnoticed. Near a
// grazing (kNearGrazing of the unit) is then a gap below 2 % of the half-swing, as 1e-3 rad is at
// 0.05 rad: a larger share counts the moderately slow impacts of a motion at a fold as a grazing's.
double state_unit(const PeriodicOrbit& start) {
  return std::clamp(20.0 * half_swing(start), 1e-3, 1.0);
}

// The continuation works in scaled unknowns v = (x with speeds times sqrt(R/g), over the state's
// unit (state_unit), (p − p0)/unit), so that a step of arclength weighs angles, speeds and the
// parameter alike (parameter_unit), whatever the motion's size. The section lies at time `phase` of
// the forcing: the stroboscopic map jumps where an impact crosses the section (the state before it
// becomes the state after it), so the phase is kept away from the impacts.
class ScaledMap {
 public:
  ScaledMap(const Model& model, const SimOptions& options, int periods,
            const std::string& parameter, double p0, double unit, double state_unit,
            const std::atomic<bool>* cancel = nullptr)
      : model_(model),
        options_(options),
        periods_(periods),
        parameter_(parameter),
        p0_(p0),
        unit_(unit),
        time_(time_scale(model)),
        state_unit_(state_unit),
        cancel_(cancel) {}

  // A point on or near the branch: the map there, its residual and Jacobian in scaled unknowns.
  struct Point {
    Vec v;
    MapPoint map;
    Vec residual;  // scaled
    Mat J;         // n × (n + 1): ∂residual/∂v
    bool ok = false;
    std::vector<std::complex<double>> multipliers;
    double norm = INFINITY;
  };

  int size() const { return 2 * model_.size(); }
  int periods() const { return periods_; }
  double phase() const { return phase_; }
  double value(const Vec& v) const { return p0_ + unit_ * v[size()]; }
  double state_unit() const { return state_unit_; }
  Vec scaled(const Vec& x, double p) const {
    Vec v(size() + 1);
    for (int k = 0; k < size(); ++k) v[k] = x[k] * (k % 2 ? time_ : 1.0) / state_unit_;
    v[size()] = (p - p0_) / unit_;
    return v;
  }
  Vec state(const Vec& v) const {
    Vec x(size());
    for (int k = 0; k < size(); ++k) x[k] = v[k] * state_unit_ / (k % 2 ? time_ : 1.0);
    return x;
  }
  // The model at parameter value p.
  Model plain(double p) const {
    Model m = model_;
    set_parameter(m, parameter_, p);
    return m;
  }
  // The same seen from the section's phase, with the limiters armed as they are there.
  Model at(double p) const { return armed_as(at_phase(plain(p), phase_), armed_); }
  const SimOptions& options() const { return options_; }
  bool cancelled() const { return cancel_ && cancel_->load(); }
  double band() const { return multiplier_band(options_); }

  Point evaluate(const Vec& v) const {
    Point pt;
    pt.v = v;
    const double p = value(v);
    if (cancelled()) return pt;
    // The model at p must be valid; the one seen from the section's phase has its psi shifted.
    if (validate_model(plain(p))) return pt;
    const Model m = at(p);
    pt.map = stroboscopic_map(m, options_, periods_, state(v));
    if (!pt.map.ok) return pt;
    const int n = size();
    const Vec r = orbit_residual(pt.map);
    Mat D = Mat::Identity(n, n) / state_unit_;
    for (int k = 1; k < n; k += 2) D(k, k) = time_ / state_unit_;
    pt.residual = D * r;
    pt.J.resize(n, n + 1);
    pt.J.leftCols(n) = D * (pt.map.jacobian - Mat::Identity(n, n)) * D.inverse();
    // The parameter's column by central differences of the map: the saltations give the state's.
    const double h = 1e-6 * std::max(std::abs(p), std::abs(unit_));
    const MapPoint up = stroboscopic_map(at(p + h), options_, periods_, state(v));
    const MapPoint down = stroboscopic_map(at(p - h), options_, periods_, state(v));
    if (!up.ok || !down.ok) return pt;
    pt.J.col(n) = D * (up.image - down.image) / (2.0 * h) * unit_;
    const Eigen::EigenSolver<Mat> eig(pt.map.jacobian, false);
    for (Eigen::Index k = 0; k < eig.eigenvalues().size(); ++k)
      pt.multipliers.push_back(eig.eigenvalues()[k]);
    std::sort(pt.multipliers.begin(), pt.multipliers.end(),
              [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    pt.norm = residual_norm(model_, r);
    pt.ok = true;
    return pt;
  }

  // The state `dt` later along the motion from x at the section, at value p, and the limiters
  // armed there in `armed`.
  Vec advance(const Vec& x, double p, double dt, std::vector<bool>& armed) const {
    armed = armed_;
    if (!(dt > 0.0)) return x;
    return run_from(at(p), options_, x, dt, &armed).value_or(x);
  }

  // Moves the section `dt` later; returns the point's state there.
  Vec shift_phase(const Point& pt, double dt) {
    const Vec x = advance(state(pt.v), value(pt.v), dt, armed_);
    phase_ += dt;
    return x;
  }

  // The state of a point on the stroboscopic section t = k·T.
  std::vector<PhasePoint> section_state(const Vec& v) const {
    const double T = forcing_period(at(value(v)));
    const double dt = T * std::ceil(phase_ / T - 1e-12) - phase_;
    std::vector<bool> armed;
    const Vec x = advance(state(v), value(v), dt, armed);
    std::vector<PhasePoint> out;
    for (Eigen::Index k = 0; k + 1 < x.size(); k += 2) out.push_back({x[k], x[k + 1]});
    return out;
  }

 private:
  const Model& model_;
  const SimOptions& options_;
  int periods_;
  std::string parameter_;
  double p0_, unit_, time_, state_unit_;
  const std::atomic<bool>* cancel_;  // once set, every point is not ok: the walk ends soon
  double phase_ = 0.0;
  std::vector<bool> armed_ = armed_at_start(model_);  // the mobile limiters' at the phase
};

using Point = ScaledMap::Point;

bool is_impact(const Event& e) {
  return e.kind == EventKind::limiter || e.kind == EventKind::collision ||
         e.kind == EventKind::chatter;
}

// The unit tangent at a point, oriented along `previous`: the null vector of J bordered by it.
Vec tangent(const Point& pt, const Vec& previous) {
  const int n = static_cast<int>(pt.J.rows());
  Mat A(n + 1, n + 1);
  A.topRows(n) = pt.J;
  A.row(n) = previous.transpose();
  Vec rhs = Vec::Zero(n + 1);
  rhs[n] = 1.0;
  const Vec t = A.fullPivLu().solve(rhs);
  return t / t.norm();
}

// Newton's method on the map's residual and the pseudo-arclength condition t·(v − predicted) = 0.
Point correct(const ScaledMap& map, const Vec& predicted, const Vec& t, double tol) {
  Point pt = map.evaluate(predicted);
  const int n = map.size();
  for (int it = 0; it < 12 && pt.ok; ++it) {
    Mat A(n + 1, n + 1);
    A.topRows(n) = pt.J;
    A.row(n) = t.transpose();
    Vec rhs(n + 1);
    rhs.head(n) = -pt.residual;
    rhs[n] = -t.dot(pt.v - predicted);
    const Vec dv = A.fullPivLu().solve(rhs);
    if (!dv.allFinite()) break;
    pt = map.evaluate(pt.v + dv);
    if (pt.ok && pt.norm <= tol && dv.lpNorm<Eigen::Infinity>() < 1e-7) return pt;
  }
  pt.ok = pt.ok && pt.norm <= tol;
  return pt;
}

// The motion's impacts over one return, as a cycle: the same impacts seen from another phase
// are the same pattern.
std::vector<std::string> impact_pattern(const RunResult& run) {
  std::vector<std::string> out;
  for (const Event& e : run.events) {
    if (!is_impact(e)) continue;
    std::ostringstream s;
    s << event_kind_name(e.kind) << e.limiter;
    for (int i : e.pellets) s << ':' << i;
    out.push_back(s.str());
  }
  std::vector<std::string> least = out;
  for (std::size_t k = 1; k < out.size(); ++k) {
    std::rotate(out.begin(), out.begin() + 1, out.end());
    least = std::min(least, out);
  }
  return least;
}

// What the bifurcations are told by: signs and counts that change across one.
struct Signature {
  double fold = 0.0;       // the tangent's parameter component
  double doubling = 0.0;   // det(M + I): a real multiplier through −1
  int unstable_pairs = 0;  // complex multipliers outside the unit circle
  std::vector<std::string> impacts;
};

// Multipliers within `band` of the unit circle are neutral: they count neither way, so that an
// area-preserving branch (on the circle to round-off) shows no Neimark–Sacker.
Signature signature(const Point& pt, const Vec& t, double band) {
  Signature s;
  s.fold = t[t.size() - 1];
  std::complex<double> det = 1.0;
  for (const auto& mu : pt.multipliers) {
    det *= mu + 1.0;
    if (std::abs(mu.imag()) > 1e-9 * std::abs(mu) && std::abs(mu) > 1.0 + band) ++s.unstable_pairs;
  }
  s.doubling = det.real();
  s.impacts = impact_pattern(pt.map.run);
  return s;
}

bool crossed(BifurcationKind k, const Signature& a, const Signature& b) {
  switch (k) {
    case BifurcationKind::fold:
      return (a.fold > 0.0) != (b.fold > 0.0);
    case BifurcationKind::period_doubling:
      return (a.doubling > 0.0) != (b.doubling > 0.0);
    case BifurcationKind::neimark_sacker:
      return a.unstable_pairs != b.unstable_pairs;
    case BifurcationKind::grazing:
      return a.impacts != b.impacts;
  }
  return false;
}

// Where a motion is near a grazing: an impact's speed (times the time scale) or a turn's distance
// to a limiter below this, of the state's unit (state_unit): 1e-3 rad for motions of a half-swing
// of 0.05 rad or more. A gap is small only against the motion's own size: at a swing of 1e-3 rad
// every impact would be slow and every turn near a limiter by an absolute 1e-3 rad.
constexpr double kNearGrazing = 1e-3;

// The turn of the motion that comes nearest to a limiter acting on its pellet, as the impact it
// becomes where it reaches the limiter, its distance to it (rad) and its time (s from the
// section); none without a turn.
struct Turn : GrazingImpact {
  double gap = INFINITY;
  double t = 0.0;
};

Turn nearest_turn(const Model& model, const RunResult& run) {
  Turn g;
  double nearest = INFINITY;
  for (const Event& e : run.events) {
    if (e.kind != EventKind::reversal) continue;
    for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
      if (!model.limiters[l].acts_on(e.pellets[0])) continue;
      const double gap = wrap_angle(model.limiters[l].angle - e.phi);
      if (std::abs(gap) >= nearest) continue;
      nearest = std::abs(gap);
      g = {{e.pellets[0], l, gap > 0.0 ? 1.0 : -1.0}, std::abs(gap), e.t};
    }
  }
  return g;
}

// The nearest an impact, or a turn nearer a limiter than `near` (rad), comes to the section, and
// the middle of the longest stretch without them, as times from the section (s). Such a turn is
// where an impact appears at the grazing: on the section, the grazing motion's state would lie on
// the limiter, and the impacting motions past it would start at their impact.
struct Clearance {
  double nearest = INFINITY;
  double middle = 0.0;
};

Clearance clearance(const Model& model, const RunResult& run, double near, double span) {
  std::vector<double> times = {0.0};
  for (const Event& e : run.events)
    if (is_impact(e)) times.push_back(e.t);
  if (const Turn turn = nearest_turn(model, run); turn.gap < near) times.push_back(turn.t);
  std::sort(times.begin(), times.end());
  times.push_back(span);
  Clearance c;
  double longest = -1.0;
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (times[k] - times[k - 1] > longest) {
      longest = times[k] - times[k - 1];
      c.middle = 0.5 * (times[k] + times[k - 1]);
    }
    if (k < times.size() - 1) c.nearest = std::min({c.nearest, times[k], span - times[k]});
  }
  return c;
}

// How near the motion is to a grazing, rad (speeds times the time scale): the slowest impact, the
// turn that comes nearest to a limiter, or the section's own state x near a limiter (a turn on
// the section is no event of the map's run). At zero an impact appears or vanishes, and the map
// has a square root there that Newton's method cannot step across.
double grazing_distance(const Model& model, const RunResult& run, const Vec& x) {
  const double time = time_scale(model);
  double d = INFINITY;
  for (int i = 0; i < model.size(); ++i)
    for (const Limiter& l : model.limiters)
      if (l.acts_on(i))
        d = std::min(d, std::abs(wrap_angle(x[2 * i] - l.angle)) + std::abs(x[2 * i + 1]) * time);
  for (const Event& e : run.events) {
    if (e.kind == EventKind::limiter) d = std::min(d, std::abs(e.dphi_before[0]) * time);
    if (e.kind == EventKind::collision)
      d = std::min(d, std::abs(e.dphi_before[0] - e.dphi_before[1]) * time);
    if (e.kind != EventKind::reversal) continue;
    for (const Limiter& l : model.limiters)
      if (l.acts_on(e.pellets[0])) d = std::min(d, std::abs(wrap_angle(e.phi - l.angle)));
  }
  return d;
}

// Limiter impacts and collisions over one return of the map.
int impacts_per_return(const Point& pt) {
  int impacts = 0;
  for (const Event& e : pt.map.run.events)
    impacts += e.kind == EventKind::limiter || e.kind == EventKind::collision;
  return impacts;
}

BranchPoint branch_point(const ScaledMap& map, const Point& pt) {
  return {map.value(pt.v),
          map.section_state(pt.v),
          pt.multipliers,
          inside_unit_circle(pt.multipliers, map.band()),
          static_cast<double>(impacts_per_return(pt)) / map.periods(),
          neutral_within(pt.multipliers, map.band())};
}

// Whether the located point is what its kind says: a multiplier at −1 for a period doubling, a
// complex pair on the unit circle for Neimark–Sacker. The signs that tell them also change where
// a multiplier passes through infinity (a motion through the inverted position, where the map's
// derivative is unbounded), which is neither.
bool confirmed(BifurcationKind kind, const Point& at) {
  for (const auto& mu : at.multipliers) {
    if (kind == BifurcationKind::period_doubling && std::abs(mu + 1.0) < 0.05) return true;
    if (kind == BifurcationKind::neimark_sacker && std::abs(mu.imag()) > 1e-9 &&
        std::abs(std::abs(mu) - 1.0) < 0.05)
      return true;
  }
  return kind == BifurcationKind::fold || kind == BifurcationKind::grazing;
}

// Locates a bifurcation of `kind` inside the step from `here` (signature `sig`) along t by ds:
// bisection on corrections at fractions of the step.
Point locate(const ScaledMap& map, BifurcationKind kind, const Point& here, const Signature& sig,
             const Vec& t, double ds, const Point& next, double tol) {
  double lo = 0.0, hi = 1.0;
  Point at = next;
  for (int k = 0; k < 40 && (hi - lo) * ds > 1e-10; ++k) {
    const double mid = 0.5 * (lo + hi);
    const Point p = correct(map, here.v + mid * ds * t, t, tol);
    if (!p.ok) break;
    if (crossed(kind, sig, signature(p, tangent(p, t), map.band()))) {
      hi = mid;
      at = p;
    } else {
      lo = mid;
    }
  }
  return at;
}

// Past a period doubling (on the side where the branch is unstable, `past` = ±1), the period-2
// motion it sheds: sought from the doubling's state moved along the eigenvector of the multiplier
// −1 (by 1e-2 to 0.3 of the state's unit), farther and farther until Newton's method finds a
// motion that one period does not return.
void find_doubled(const ScaledMap& map, const Point& at, double past, double unit, Bifurcation& b) {
  const Eigen::EigenSolver<Mat> eig(at.map.jacobian, true);
  Eigen::Index nearest = 0;
  for (Eigen::Index k = 1; k < eig.eigenvalues().size(); ++k)
    if (std::abs(eig.eigenvalues()[k] + 1.0) < std::abs(eig.eigenvalues()[nearest] + 1.0))
      nearest = k;
  const Vec v = eig.eigenvectors().col(nearest).real();
  const double value = map.value(at.v) + past * 0.02 * std::abs(unit);
  const Model m = map.plain(value);
  if (validate_model(m)) return;
  for (double a : {1e-2, 3e-2, 0.1, 0.3}) {
    for (double side : {1.0, -1.0}) {
      if (map.cancelled()) return;
      Vec moved = at.v;
      moved.head(map.size()) +=
          side * a *
          map.scaled(map.state_unit() * v / v.lpNorm<Eigen::Infinity>(), 0.0).head(map.size());
      OrbitSpec spec;
      spec.periods = 2 * map.periods();
      spec.guess = map.section_state(moved);
      const PeriodicOrbit two = find_periodic_orbit(m, map.options(), spec);
      if (!two.converged) continue;
      Vec x(map.size());
      for (std::size_t i = 0; i < two.state.size(); ++i)
        x.segment(2 * i, 2) << two.state[i].phi, two.state[i].dphi;
      const MapPoint once = stroboscopic_map(m, map.options(), map.periods(), x);
      if (once.ok && residual_norm(m, orbit_residual(once)) > 1e-6) {
        b.doubled_value = value;
        b.doubled_state = two.state;
        return;
      }
    }
  }
}

// The limiter impact a branch's motion makes slowest, whose speed vanishes at a grazing.
struct SlowImpact : GrazingImpact {
  double speed = INFINITY;
};

SlowImpact slowest_impact(const RunResult& run) {
  SlowImpact s;
  for (const Event& e : run.events)
    if (e.kind == EventKind::limiter && std::abs(e.dphi_before[0]) < s.speed)
      s = {{e.pellets[0], e.limiter, e.dphi_before[0] > 0.0 ? 1.0 : -1.0},
           std::abs(e.dphi_before[0])};
  return s;
}

// The free motion near x at the model m and how far its turn goes past the limiter (rad, > 0:
// it would cross it; 0 at the grazing) at its turn `turn` s after the section, or none where it is
// not found.
struct FreeMotion {
  Vec x;
  double overshoot = 0.0;
  double turn = 0.0;
};
std::optional<FreeMotion> free_motion(const Model& m, const SimOptions& options, int periods,
                                      const Vec& x, const GrazingImpact& slow, double angle) {
  OrbitSpec spec;
  spec.periods = periods;
  spec.transient = 0;
  for (Eigen::Index k = 0; k + 1 < x.size(); k += 2) spec.guess.push_back({x[k], x[k + 1]});
  const PeriodicOrbit o = find_periodic_orbit(m, options, spec);
  if (!o.converged) return std::nullopt;
  FreeMotion f{Vec(x.size()), -INFINITY, 0.0};
  for (std::size_t i = 0; i < o.state.size(); ++i)
    f.x.segment(2 * i, 2) << o.state[i].phi, o.state[i].dphi;
  for (const Event& e : o.events) {
    if (e.kind != EventKind::reversal || e.pellets[0] != slow.pellet) continue;
    const double overshoot = slow.side * wrap_angle(e.phi - angle);
    if (overshoot > f.overshoot) f.overshoot = overshoot, f.turn = e.t;
  }
  if (!std::isfinite(f.overshoot)) return std::nullopt;
  return f;
}

// One continuation: the branch so far, the point it stands on with its tangent and signature, and
// the arclength step. Each member is one move of the pseudo-arclength walk.
class Continuation {
 public:
  Continuation(const Model& model, const SimOptions& options, const PeriodicOrbit& start,
               const ContinuationSpec& spec, const std::function<void(double)>& progress,
               const std::atomic<bool>* cancel)
      : spec_(spec),
        progress_(progress),
        cancel_(cancel),
        section_(armed_as(model, start.armed)),
        p0_(*get_parameter(model, spec.parameter)),
        unit_(parameter_unit(p0_, spec.to - p0_)),
        end_((spec.to - p0_) / unit_),
        map_(section_, options, start.periods, spec.parameter, p0_, unit_, state_unit(start),
             cancel),
        tol_(std::max(1e-10, 100.0 * options.rtol)),
        n_(map_.size()) {
    Vec x(n_);
    for (int i = 0; i < model.size(); ++i)
      x.segment(2 * i, 2) << start.state[i].phi, start.state[i].dphi;
    here_ = map_.evaluate(map_.scaled(x, p0_));
    t_ = Vec::Zero(n_ + 1);
    t_[n_] = 1.0;  // toward `to`: the scaled parameter grows to end_
  }

  OrbitBranch run();

 private:
  // A corrected point ahead, with its tangent and signature.
  struct Step {
    Point point;
    Vec t;
    Signature sig;
  };

  bool cancelled() const { return cancel_ && cancel_->load(); }
  Step step_to(const Vec& predicted) const;
  void keep_clear();
  bool cross_grazing();
  bool jump_grazing();
  bool jump_from_impacting(const SlowImpact& slow);
  bool jump_from_free(const Turn& turn);
  std::optional<Point> impacting_at(const GrazingImpact& impact, double p, double time,
                                    const Vec& before) const;
  std::optional<Step> step_on_impact(const GrazingImpact& impact, double p) const;
  bool take(Step next);
  void walk_off_grazing(const GrazingImpact& impact, double grazing);
  bool walk_on_impact();
  void report_grazing(double value, const Vec& x, bool impacting);
  bool admit(const Point& pt);
  bool record(const Point& pt);
  void restart_at(Point next, bool turned = false);
  // The way the branch goes in the parameter's own units (+1: to larger values).
  double heading() const { return t_[n_] * unit_ > 0.0 ? 1.0 : -1.0; }
  // How near zero a gap must come to count as near a grazing, rad (kNearGrazing).
  double near_grazing() const { return kNearGrazing * map_.state_unit(); }
  // How far the parameter may go from `from` the way `way` (±1): to `to` where that lies ahead,
  // unbounded where the branch heads away from it (turned back at a fold or a grazing).
  double room(double from, double way) const {
    return (spec_.to - from) * way > 0.0 ? std::abs(spec_.to - from) : INFINITY;
  }
  struct Grazing;
  std::optional<Grazing> grazing_across(const Step& next) const;
  bool lands_elsewhere(const Step& next) const;
  struct Grazing {
    double value;
    Vec x, beyond;  // the grazing motion's state, and the free motion's on its far side
    double turn;    // the time of the grazing motion's turn at the limiter, s after the section
  };
  std::optional<Grazing> grazing_ahead(const GrazingImpact& impact, bool impacting) const;
  Grazing refine_grazing(const GrazingImpact& slow, double angle, double pa, FreeMotion a,
                         double pb, FreeMotion b) const;
  std::optional<FreeMotion> free_at(const GrazingImpact& slow, double angle, double p,
                                    const Vec& x) const {
    return free_motion(without_limiter(map_.at(p), slow.limiter), map_.options(), map_.periods(), x,
                       slow, angle);
  }
  std::optional<std::pair<Point, double>> point_past_grazing(double way) const;
  std::vector<BranchPoint> walk_back(const Point& across, double step, double way) const;
  void note_bifurcations(const Step& next);
  bool past_to(const Point& next) const {
    return (map_.value(next.v) - spec_.to) * (unit_ > 0 ? 1 : -1) >= 0.0;
  }
  void finish_at_to(const Point& next);
  void move_to(Step next);
  Vec along_parameter() const {
    Vec fixed = Vec::Zero(n_ + 1);
    fixed[n_] = 1.0;
    return fixed;
  }

  static constexpr double kStepMin = 1e-7, kStepMax = 0.1;
  // Steps across a grazing no free motion confirms are shortened down to this (lands_elsewhere).
  static constexpr double kGrazingStep = 1e-3;
  const ContinuationSpec& spec_;
  const std::function<void(double)>& progress_;
  const std::atomic<bool>* cancel_;
  const Model section_;  // the limiters armed as at the start's section
  const double p0_;
  const double unit_, end_;  // the parameter's unit (parameter_unit) and `to` scaled
  ScaledMap map_;
  const double tol_;
  const int n_;
  OrbitBranch branch_;
  Point here_;
  Vec t_;
  Signature sig_;
  double ds_ = 0.0;
  std::size_t jump_tried_at_ = 0;  // branch points when the last grazing jump was tried
  double walk_ = 2e-3;             // walk_on_impact's step, of the unit
  bool ended_ = false;             // a point was inadmissible (admit): the branch ends before it
};

OrbitBranch Continuation::run() {
  if (cancelled()) {
    branch_.message = "cancelled";
    return branch_;
  }
  if (!here_.ok) {
    branch_.message = "the start is no orbit the map can follow: " + here_.map.run.stats.message;
    return branch_;
  }
  keep_clear();
  t_ = tangent(here_, t_);
  sig_ = signature(here_, t_, map_.band());
  record(here_);
  ds_ = std::min(0.05, 2.0 / spec_.max_points);
  while (static_cast<int>(branch_.points.size()) < spec_.max_points) {
    if (ended_) return branch_;
    if (cancelled()) {
      branch_.message = "cancelled";
      return branch_;
    }
    // Steps shrunk to a crawl with a slow impact on the branch: the square root of a grazing
    // ahead, which the corrector only creeps toward. Jump to it instead where it is one.
    if (ds_ < 1e-3 && branch_.points.size() >= jump_tried_at_ + 5) {
      jump_tried_at_ = branch_.points.size();
      if (jump_grazing()) {
        if (branch_.reached) return branch_;
        continue;
      }
    }
    Step next = step_to(here_.v + ds_ * t_);
    if (!next.point.ok) {
      if (walk_on_impact()) {
        if (branch_.reached) return branch_;
        continue;
      }
      ds_ /= 2.0;
      if (ds_ >= kStepMin || cross_grazing()) continue;
      return branch_;
    }
    if (ds_ > kGrazingStep && lands_elsewhere(next)) {
      ds_ /= 2.0;
      continue;
    }
    note_bifurcations(next);
    if (past_to(next.point)) {
      finish_at_to(next.point);
      return branch_;
    }
    move_to(std::move(next));
  }
  if (ended_) return branch_;
  std::ostringstream why;
  why << "stopped at " << spec_.parameter << " = " << branch_.points.back().value << " after "
      << spec_.max_points << " points (periodic_orbit.continuation.max_points)";
  branch_.message = why.str();
  return branch_;
}

// The corrected point near `predicted`; not ok where it strays far from its prediction, or turns
// sharply where the motion's impacts stay the same: it may have jumped to another motion.
Continuation::Step Continuation::step_to(const Vec& predicted) const {
  Step next{correct(map_, predicted, t_, tol_), {}, {}};
  if (!next.point.ok) return next;
  next.t = tangent(next.point, t_);
  next.sig = signature(next.point, next.t, map_.band());
  const bool strayed = (next.point.v - predicted).norm() > 0.5 * ds_ + 10.0 * tol_;
  const bool turned = next.sig.impacts == sig_.impacts && t_.dot(next.t) < std::cos(0.3);
  if (strayed || turned) next.point.ok = false;
  return next;
}

// Keeps the section a twentieth of a period or more away from every impact and from the turn
// that comes nearest to a limiter.
void Continuation::keep_clear() {
  const Model m = map_.at(map_.value(here_.v));
  const double T = forcing_period(m);
  const Clearance c = clearance(m, here_.map.run, near_grazing(), map_.periods() * T);
  if (c.nearest >= 0.05 * T) return;
  const Vec moved = map_.shift_phase(here_, c.middle);
  here_ = map_.evaluate(map_.scaled(moved, map_.value(here_.v)));
  Vec along = Vec::Zero(n_ + 1);
  along[n_] = t_[n_] > 0.0 ? 1.0 : -1.0;
  if (here_.ok) t_ = tangent(here_, std::abs(t_[n_]) > 0.1 ? along : t_);
}

// The steps shrank to nothing: at a grazing, records it and steps across at fixed values of the
// parameter (true), or ends the branch saying why (false).
bool Continuation::cross_grazing() {
  if (cancelled()) {
    branch_.message = "cancelled";
    return false;
  }
  std::ostringstream why;
  why << "the branch could not be followed past " << spec_.parameter << " = "
      << map_.value(here_.v);
  const Model here = map_.at(map_.value(here_.v));
  if (grazing_distance(here, here_.map.run, here_.map.x) > near_grazing()) {
    branch_.message = why.str() + ": no nearby motion continues it";
    return false;
  }
  // Approached from the impacting side where the slowest limiter impact is near a grazing and
  // nearer zero than the turn nearest a limiter (the one grazed, as in jump_grazing).
  const double slow = slowest_impact(here_.map.run).speed * time_scale(here);
  const bool impacting = slow <= near_grazing() && slow <= nearest_turn(here, here_.map.run).gap;
  branch_.bifurcations.push_back({BifurcationKind::grazing,
                                  map_.value(here_.v),
                                  map_.section_state(here_.v),
                                  {},
                                  {},
                                  impacting});
  const double way = t_[n_] > 0.0 ? 1.0 : -1.0;
  std::optional<std::pair<Point, double>> across = point_past_grazing(way);
  if (!across) {
    branch_.message = why.str() + ": it ends at a grazing there (an impact of zero speed), " +
                      "and no motion past it continues it";
    return false;
  }
  const std::vector<BranchPoint> nearer = walk_back(across->first, across->second, way);
  branch_.points.insert(branch_.points.end(), nearer.rbegin(), nearer.rend());
  restart_at(std::move(across->first));
  return true;
}

// The grazing between pa, whose free motion overshoots the limiter (a), and pb, whose does not
// (b): Illinois regula falsi on the overshoot, a smooth function of the parameter.
Continuation::Grazing Continuation::refine_grazing(const GrazingImpact& slow, double angle,
                                                   double pa, FreeMotion a, double pb,
                                                   FreeMotion b) const {
  double ha = a.overshoot, hb = b.overshoot;
  int last = 0;
  for (int k = 0; k < 60 && std::abs(pb - pa) > 1e-14 * std::abs(pa) && ha != 0.0; ++k) {
    const double pc = (pa * hb - pb * ha) / (hb - ha);
    const std::optional<FreeMotion> c = free_at(slow, angle, pc, a.x);
    if (!c) break;
    if (c->overshoot > 0.0) {
      pa = pc, ha = c->overshoot, a = *c;
      if (last == -1) hb /= 2.0;
      last = -1;
    } else {
      pb = pc, hb = c->overshoot, b = *c;
      if (last == 1) ha /= 2.0;
      last = 1;
    }
  }
  return std::abs(ha) < std::abs(hb) ? Grazing{pa, a.x, b.x, a.turn}
                                     : Grazing{pb, b.x, b.x, b.turn};
}

// The grazing between here and `next` where one of them has a limiter impact the other lacks,
// located on the free motion; none where it is not that.
std::optional<Continuation::Grazing> Continuation::grazing_across(const Step& next) const {
  const SlowImpact h = slowest_impact(here_.map.run), n = slowest_impact(next.point.map.run);
  const bool from_here = h.pellet >= 0 && n.limiter != h.limiter;
  if (!from_here && !(n.pellet >= 0 && h.limiter != n.limiter)) return std::nullopt;
  const SlowImpact& slow = from_here ? h : n;
  const Point& impacting = from_here ? here_ : next.point;
  const Point& free = from_here ? next.point : here_;
  for (const Limiter& l : map_.at(map_.value(here_.v)).limiters)
    if (l.mobile) return std::nullopt;
  const double angle = map_.at(map_.value(here_.v)).limiters[slow.limiter].angle;
  const double pa = map_.value(impacting.v), pb = map_.value(free.v);
  const std::optional<FreeMotion> b = free_at(slow, angle, pb, map_.state(free.v));
  // Far from the grazing the impacting motion's state is far from the free motion's: the free
  // motion on the other side is then the nearer guess.
  std::optional<FreeMotion> a = free_at(slow, angle, pa, map_.state(impacting.v));
  if (!a && b) a = free_at(slow, angle, pa, b->x);
  if (!a || !b || !(a->overshoot > 0.0) || !(b->overshoot < 0.0)) return std::nullopt;
  return refine_grazing(slow, angle, pa, *a, pb, *b);
}

// Whether the step to `next` gains or loses a fixed limiter's impact (the slowest limiter impact
// of the motion on one side is on a limiter the other's does not strike first) with no grazing of
// that limiter between them (grazing_across): near a grazing other motions coexist close by, and
// a long step can land on one of them instead of crossing the grazing.
bool Continuation::lands_elsewhere(const Step& next) const {
  if (!crossed(BifurcationKind::grazing, sig_, next.sig)) return false;
  const SlowImpact h = slowest_impact(here_.map.run), n = slowest_impact(next.point.map.run);
  const bool limiter_changes =
      (h.pellet >= 0 && n.limiter != h.limiter) || (n.pellet >= 0 && h.limiter != n.limiter);
  if (!limiter_changes) return false;
  for (const Limiter& l : map_.at(map_.value(here_.v)).limiters)
    if (l.mobile) return false;
  return !grazing_across(next);
}

// The grazing of `impact` ahead of the branch: the free motion (the scene without that limiter) at
// the branch's value and at values further on (1e-3 to 0.1 of the unit, not past `to` ahead) until
// the overshoot of its turn past the limiter changes sign, located by refine_grazing. `impacting`:
// the branch's motion has that impact (the free motion overshoots here). None where the sign does
// not change.
std::optional<Continuation::Grazing> Continuation::grazing_ahead(const GrazingImpact& impact,
                                                                 bool impacting) const {
  const double angle = map_.at(map_.value(here_.v)).limiters[impact.limiter].angle;
  const double p0 = map_.value(here_.v);
  const std::optional<FreeMotion> here = free_at(impact, angle, p0, map_.state(here_.v));
  if (!here || (here->overshoot > 0.0) != impacting) return std::nullopt;
  for (double d : {1e-3, 1e-2, 3e-2, 0.1}) {
    double p = p0 + heading() * d * std::abs(unit_);
    if (room(p0, heading()) < INFINITY && (p - spec_.to) * heading() > 0.0) p = spec_.to;
    const std::optional<FreeMotion> there = free_at(impact, angle, p, here->x);
    if (!there || (there->overshoot > 0.0) == impacting) continue;
    return impacting ? refine_grazing(impact, angle, p0, *here, p, *there)
                     : refine_grazing(impact, angle, p, *there, p0, *here);
  }
  return std::nullopt;
}

// Steps shrunk to a crawl near a grazing, where the map has a square root that the corrector
// only creeps toward (from the impacting side) or cannot step across (from the other): the
// grazing is located on the free motion, reported, and the branch goes on a step past it (true);
// false where this is no such grazing. Fixed limiters only.
bool Continuation::jump_grazing() {
  for (const Limiter& l : map_.at(map_.value(here_.v)).limiters)
    if (l.mobile) return false;
  // The stop grazed is the limiter whose gap's minimum touches zero: the slowest limiter impact
  // (its speed times the time scale) or the turn nearest a limiter, whichever is nearer zero. A
  // motion that strikes one stop fast may graze another from its free side.
  const Model here = map_.at(map_.value(here_.v));
  const SlowImpact slow = slowest_impact(here_.map.run);
  const Turn turn = nearest_turn(here, here_.map.run);
  if (slow.pellet >= 0 && (turn.pellet < 0 || slow.speed * time_scale(here) <= turn.gap))
    return jump_from_impacting(slow);
  return jump_from_free(turn);
}

// On the impacting side near a grazing: the impact's speed goes to zero like a square root of
// the distance to it, and the corrector creeps. The grazing motion is the free motion (the one
// the limiter does not touch) whose turn just reaches the limiter, smooth in the parameter: the
// branch goes on from the free motion a step past it, where the limiter is back.
bool Continuation::jump_from_impacting(const SlowImpact& slow) {
  const std::optional<Grazing> g = grazing_ahead(slow, true);
  if (!g) return false;
  const double angle = map_.at(map_.value(here_.v)).limiters[slow.limiter].angle;
  const double pn =
      g->value + heading() * std::min(1e-3 * std::abs(unit_), room(g->value, heading()));
  const std::optional<FreeMotion> n = free_at(slow, angle, pn, g->beyond);
  if (!n || n->overshoot >= 0.0) return false;
  Point next = map_.evaluate(map_.scaled(n->x, pn));
  if (!next.ok || slowest_impact(next.map.run).limiter == slow.limiter) return false;
  report_grazing(g->value, g->x, true);
  restart_at(std::move(next));
  return true;
}

// On the non-impacting side near a grazing: the turn of the branch's motion nearest a limiter
// reaches it. Past it the motion strikes the limiter, at a speed growing linearly from zero, which
// the corrector on the map cannot step onto (the square root): the impacting motion a step past
// the grazing is solved on the impact instead (core/analysis/grazing_orbit.h), from the grazing
// motion, and the branch goes on from it.
bool Continuation::jump_from_free(const Turn& turn) {
  if (turn.pellet < 0) return false;
  const std::optional<Grazing> g = grazing_ahead(turn, false);
  if (!g) return false;
  // Past the grazing the impacting motion is sought first; where the only one there strikes
  // moving away from the limiter (no impact at all), the impacting motions lie on the side the
  // branch came from: the branch turns back at the grazing (a fold of the branch there) and
  // goes on along them, the parameter heading back.
  for (const double way : {1.0, -1.0}) {
    const double pn =
        g->value +
        way * heading() * std::min(1e-3 * std::abs(unit_), room(g->value, way * heading()));
    const std::optional<Vec> before =
        run_from(without_limiter(map_.at(pn), turn.limiter), map_.options(), g->x, g->turn);
    if (!before) continue;
    std::optional<Point> next = impacting_at(turn, pn, g->turn, *before);
    if (!next) continue;
    report_grazing(g->value, g->x, false);
    restart_at(std::move(*next), way < 0.0);
    walk_off_grazing(turn, g->value);
    return true;
  }
  return false;
}

// The impacting motion at value p, solved on the impact from a guess of its time and the state
// before it, and checked on the map: a motion the map returns (to tol_) whose slowest impact is on
// the limiter. None where it is not that.
std::optional<Point> Continuation::impacting_at(const GrazingImpact& impact, double p, double time,
                                                const Vec& before) const {
  const std::optional<ImpactingOrbit> o =
      impacting_orbit(map_.at(p), map_.options(), map_.periods(), impact, time, before, tol_);
  if (!o) return std::nullopt;
  Point pt = map_.evaluate(map_.scaled(o->x, p));
  if (!pt.ok || pt.norm > tol_ || slowest_impact(pt.map.run).limiter != impact.limiter)
    return std::nullopt;
  return pt;
}

// The branch's motion at value p solved on `impact` (an impact of the motion here), from the
// state just before that impact here: a step of the branch, its bifurcations not yet noted. None
// where it is not found.
std::optional<Continuation::Step> Continuation::step_on_impact(const GrazingImpact& impact,
                                                               double p) const {
  double time = 0.0;
  for (const Event& e : here_.map.run.events)
    if (e.kind == EventKind::limiter && e.limiter == impact.limiter) time = e.t;
  const std::optional<Vec> before =
      run_from(without_limiter(map_.at(map_.value(here_.v)), impact.limiter), map_.options(),
               map_.state(here_.v), time);
  if (!before) return std::nullopt;
  std::optional<Point> at = impacting_at(impact, p, time, *before);
  if (!at) return std::nullopt;
  Step next{std::move(*at), {}, {}};
  next.t = tangent(next.point, t_);
  next.sig = signature(next.point, next.t, map_.band());
  return next;
}

// Takes `next` as the branch's next point, its bifurcations noted; false where it is past `to`
// (the branch then ends there).
bool Continuation::take(Step next) {
  if (ended_) return false;
  note_bifurcations(next);
  if (past_to(next.point)) {
    finish_at_to(next.point);
    return false;
  }
  move_to(std::move(next));
  return !ended_;
}

// Just past a grazing from the non-impacting side the map's square root is still close: the
// corrector's steps would crawl. The branch walks away from the grazing on the impact instead, at
// distances doubling from 2e-3 to 0.032 of the unit (not past `to`), each motion solved from the
// last one's impact and taken as a step of the branch, its bifurcations noted; it stops early
// where a motion is not found, and the corrector goes on from the last.
void Continuation::walk_off_grazing(const GrazingImpact& impact, double grazing) {
  const double way = heading();
  for (double d = 2e-3; d < 0.05; d *= 2.0) {
    if (cancelled() || static_cast<int>(branch_.points.size()) >= spec_.max_points) return;
    const double p = grazing + way * std::min(d * std::abs(unit_), room(grazing, way));
    std::optional<Step> next = step_on_impact(impact, p);
    if (!next || !take(std::move(*next))) return;
  }
}

// The corrector on the map crawls (steps below 1e-3) on a motion with a slow limiter impact (its
// speed times the time scale below near_grazing): near a grazing the map's square root leaves
// Newton's method a small basin, and from a predictor off the branch it cycles between a motion
// with the impact and one without. The next point is solved on that impact instead, smooth there,
// a parameter step of walk_ of the unit on (doubled after each success, halved after a failure,
// from 1e-5 to 0.1); true where it was found (and taken: the branch may have reached `to`).
bool Continuation::walk_on_impact() {
  if (ds_ >= 1e-3 || walk_ < 1e-5) return false;
  const Model here = map_.at(map_.value(here_.v));
  for (const Limiter& l : here.limiters)
    if (l.mobile) return false;
  const SlowImpact slow = slowest_impact(here_.map.run);
  if (slow.pellet < 0 || slow.speed * time_scale(here) > near_grazing()) return false;
  const double from = map_.value(here_.v);
  const double p = from + heading() * std::min(walk_ * std::abs(unit_), room(from, heading()));
  std::optional<Step> next = step_on_impact(slow, p);
  if (!next || slowest_impact(next->point.map.run).limiter != slow.limiter) {
    walk_ /= 2.0;
    return false;
  }
  walk_ = std::min(0.1, 2.0 * walk_);
  take(std::move(*next));
  return true;
}

// Records a grazing at `value`, where the motion's state on the section is x, approached from the
// side where the motion has the impact (`impacting`) or not, and draws the grazing motion.
// A grazing already reported at that value, approached from the same side, closes the branch on
// itself (an isola: the jumps through its grazings lead round it): the branch ends there, saying
// so, instead of going round again.
void Continuation::report_grazing(double value, const Vec& x, bool impacting) {
  for (const Bifurcation& b : branch_.bifurcations)
    if (b.kind == BifurcationKind::grazing && b.approached_impacting == impacting &&
        std::abs(b.value - value) <= 1e-6 * std::abs(unit_)) {
      std::ostringstream why;
      why << "the branch closes on itself at the grazing at " << spec_.parameter << " = " << value
          << ", met before: it does not reach " << spec_.to;
      branch_.message = why.str();
      ended_ = true;
      return;
    }
  const Vec v = map_.scaled(x, value);
  branch_.bifurcations.push_back(
      {BifurcationKind::grazing, value, map_.section_state(v), {}, {}, impacting});
  const Point at = map_.evaluate(v);
  if (at.ok) record(at);
}

// Whether the motion at pt is one the scene's pellets can make: each in the turn of every fixed
// limiter acting on it that it starts in, on its own side of one it lies on (decided from its
// motion), and the pellets in the order they start in (off_own_side). The map refuses to run
// from a state that is not; this check stands at every point the branch takes, so that a jump
// that lands on another motion ends the branch, saying why, and never reaches `to` on it.
bool Continuation::admit(const Point& pt) {
  if (ended_) return false;
  const double p = map_.value(pt.v);
  const std::optional<std::string> off = off_own_side(map_.at(p), map_.state(pt.v));
  if (!off) return true;
  std::ostringstream why;
  why << "the branch ends at " << spec_.parameter << " = " << p << ": the motion there puts "
      << *off;
  branch_.message = why.str();
  branch_.reached = false;
  ended_ = true;
  return false;
}

// Adds pt to the branch where it is admissible (admit).
bool Continuation::record(const Point& pt) {
  if (!admit(pt)) return false;
  branch_.points.push_back(branch_point(map_, pt));
  return true;
}

// Goes on from `next`, a motion just past a grazing, along the parameter the way the branch went
// (back where it `turned` there), with a small step.
void Continuation::restart_at(Point next, bool turned) {
  const double way = (t_[n_] > 0.0 ? 1.0 : -1.0) * (turned ? -1.0 : 1.0);
  here_ = std::move(next);
  t_ = tangent(here_, way * along_parameter());
  keep_clear();
  sig_ = signature(here_, t_, map_.band());
  record(here_);
  ds_ = 1e-3;
}

// Past the grazing, near it: a motion at a parameter step of 1e-4 to 0.1 (scaled) with an impact
// more or less and the state close by, and the step that found it.
std::optional<std::pair<Point, double>> Continuation::point_past_grazing(double way) const {
  for (double dp : {1e-4, 1e-3, 1e-2, 3e-2, 0.1}) {
    Vec predicted = here_.v;
    predicted[n_] += way * dp;
    Point across = correct(map_, predicted, along_parameter(), tol_);
    if (across.ok && impact_pattern(across.map.run) != sig_.impacts &&
        (across.v - here_.v).head(n_).norm() < 0.3)
      return std::make_pair(std::move(across), dp);
  }
  return std::nullopt;
}

// The branch leaves a grazing like a square root: points walked back toward it from the far side
// (farthest first), so that the steep part is drawn too.
std::vector<BranchPoint> Continuation::walk_back(const Point& across, double step,
                                                 double way) const {
  std::vector<BranchPoint> nearer;
  Point walk = across;
  for (double dp = step / 2.0; dp > step / 100.0; dp /= 2.0) {
    Vec predicted = walk.v;
    predicted[n_] = here_.v[n_] + way * dp;
    const Point p = correct(map_, predicted, along_parameter(), tol_);
    if (!p.ok || off_own_side(map_.at(map_.value(p.v)), map_.state(p.v))) break;
    nearer.push_back(branch_point(map_, p));
    walk = p;
  }
  return nearer;
}

// The bifurcations inside the step to `next`, located and confirmed. At a grazing the multipliers
// jump: a sign change found at it is the grazing's own.
void Continuation::note_bifurcations(const Step& next) {
  std::optional<double> grazing;
  for (BifurcationKind kind : {BifurcationKind::grazing, BifurcationKind::fold,
                               BifurcationKind::period_doubling, BifurcationKind::neimark_sacker}) {
    if (!crossed(kind, sig_, next.sig)) continue;
    const Point at = locate(map_, kind, here_, sig_, t_, ds_, next.point, tol_);
    double value = map_.value(at.v);
    std::vector<PhasePoint> state = map_.section_state(at.v);
    // A grazing is located on the free motion, which stays smooth there (bisection on the
    // branch stalls in the square root, or where no correction lands between the two sides).
    const std::optional<Grazing> exact =
        kind == BifurcationKind::grazing ? grazing_across(next) : std::nullopt;
    if (exact) {
      value = exact->value;
      state = map_.section_state(map_.scaled(exact->x, value));
    }
    if (grazing && std::abs(value - *grazing) <= 1e-6 * std::abs(unit_)) continue;
    if (!confirmed(kind, at)) continue;
    if (kind == BifurcationKind::grazing) grazing = value;
    Bifurcation b{kind, value, std::move(state), {}, {}, {}};
    if (kind == BifurcationKind::grazing)
      b.approached_impacting = impacts_per_return(here_) > impacts_per_return(next.point);
    if (kind == BifurcationKind::period_doubling)
      find_doubled(map_, at,
                   (inside_unit_circle(here_.multipliers, map_.band()) ? 1.0 : -1.0) *
                       (t_[n_] * unit_ > 0.0 ? 1.0 : -1.0),
                   unit_, b);
    branch_.bifurcations.push_back(std::move(b));
  }
}

// The last point exactly at `to`, where the branch crosses it: corrected from `next` with the
// parameter set to `to`, or, where Newton's method does not converge from there (a long last step
// on a curved branch), from the point of the chord from here to `next` at `to`.
void Continuation::finish_at_to(const Point& next) {
  Vec on = next.v;
  on[n_] = end_;
  Point end = correct(map_, on, along_parameter(), tol_);
  if (!end.ok) {
    const double share = (end_ - here_.v[n_]) / (next.v[n_] - here_.v[n_]);
    on = here_.v + share * (next.v - here_.v);
    on[n_] = end_;
    end = correct(map_, on, along_parameter(), tol_);
  }
  if (!record(end.ok ? end : next)) return;
  branch_.reached = true;
  if (progress_) progress_(1.0);
}

void Continuation::move_to(Step next) {
  here_ = std::move(next.point);
  t_ = std::move(next.t);
  keep_clear();
  sig_ = signature(here_, t_, map_.band());
  if (!admit(here_)) return;
  // Steps shortened to a crawl (before a grazing) add nothing a figure shows.
  if (std::abs(map_.value(here_.v) - branch_.points.back().value) > 1e-6 * std::abs(unit_) ||
      ds_ > 1e-4)
    branch_.points.push_back(branch_point(map_, here_));
  if (progress_)
    progress_(std::max(static_cast<double>(branch_.points.size()) / spec_.max_points,
                       std::clamp(here_.v[n_] / end_, 0.0, 1.0)));
  ds_ = std::min(kStepMax, ds_ * 1.5);
}

}  // namespace

std::string_view bifurcation_kind_name(BifurcationKind kind) {
  switch (kind) {
    case BifurcationKind::fold:
      return "fold";
    case BifurcationKind::period_doubling:
      return "period_doubling";
    case BifurcationKind::neimark_sacker:
      return "neimark_sacker";
    case BifurcationKind::grazing:
      return "grazing";
  }
  return "fold";
}

std::optional<FieldError> validate_continuation(const Model& model, const ContinuationSpec& spec,
                                                const Limits& limits) {
  const std::string field = "periodic_orbit.continuation.";
  const std::optional<double> from = get_parameter(model, spec.parameter);
  if (!from)
    return FieldError{field + "parameter",
                      "names no numeric field of this model: \"" + spec.parameter + "\""};
  if (!std::isfinite(spec.to) || spec.to == *from)
    return FieldError{field + "to", "expected a finite value other than the parameter's own"};
  Model end = model;
  set_parameter(end, spec.parameter, spec.to);
  if (auto e = validate_model(end, limits))
    return FieldError{field + "to", "makes the model invalid: " + e->field + " " + e->message};
  if (auto e = validate_orbit(end, {}, limits))
    if (e->field.rfind("model.", 0) == 0)
      return FieldError{field + "to",
                        "leaves no periodic orbit to seek: " + e->field + " " + e->message};
  if (spec.max_points < 2 || spec.max_points > limits.branch_points)
    return FieldError{field + "max_points",
                      "expected a whole number from 2 to " + std::to_string(limits.branch_points)};
  return std::nullopt;
}

OrbitBranch continue_orbit(const Model& model, const SimOptions& options,
                           const PeriodicOrbit& start, const ContinuationSpec& spec,
                           const std::function<void(double)>& progress,
                           const std::atomic<bool>* cancel) {
  return Continuation(model, options, start, spec, progress, cancel).run();
}

}  // namespace vibro
