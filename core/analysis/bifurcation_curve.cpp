#include "core/analysis/bifurcation_curve.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "core/analysis/checked_run.h"
#include "core/model/parameter.h"
#include "core/run/deadline.h"

namespace vibro {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// The signed clearance of the map's motion to the fixed limiters, rad: of the turning points near
// a limiter that acts on its pellet (their distance from it) and the impacts (minus their speed
// times sqrt(R/g)), the one nearest zero. It passes through zero at a grazing from either side:
// a turning point reaching the limiter, or an impact's speed falling to zero (the motion's other
// impacts keep theirs). Infinity where the motion has neither.
double signed_clearance(const Model& model, const RunResult& run) {
  const double time = time_scale(model);
  double nearest = INFINITY;
  const auto take = [&nearest](double v) {
    if (std::abs(v) < std::abs(nearest)) nearest = v;
  };
  for (const Event& e : run.events) {
    if (e.kind == EventKind::limiter) take(-std::abs(e.dphi_before[0]) * time);
    if (e.kind != EventKind::reversal) continue;
    for (const Limiter& l : model.limiters)
      if (!l.mobile && l.acts_on(e.pellets[0])) take(std::abs(wrap_angle(e.phi - l.angle)));
  }
  return nearest;
}

// The clearance a followed grazing is solved for, rad: just short of touching, on the side where
// the map is smooth (at zero it has a square root, and a run may resolve an impact of vanishing
// speed as a chatter), and far below any accuracy the curve is drawn to.
constexpr double kGrazingClearance = 1e-8;

// The augmented system P(x; p1) − x = 0, G(x; p1) = 0 at one value of the second parameter,
// on the section at time `phase` of the forcing (kept away from the motion's events, where the
// map and the test function are smooth).
class Augmented {
 public:
  Augmented(const Model& model, const SimOptions& options, int periods, std::string parameter,
            BifurcationKind kind, double span, const Deadline& deadline,
            const std::atomic<bool>* cancel)
      : model_(model),
        options_(options),
        periods_(periods),
        parameter_(std::move(parameter)),
        kind_(kind),
        span_(span),
        deadline_(deadline),
        cancel_(cancel),
        tol_(multiplier_band(options)) {}

  struct Eval {
    MapPoint map;
    double g = NAN;
    bool ok = false;
  };

  bool stopped() const { return (cancel_ && cancel_->load()) || deadline_.passed(); }
  void set_model(const Model& m) { model_ = m; }
  const Model& model() const { return model_; }
  double phase() const { return phase_; }

  // The model at p1 seen from the section's phase; nothing where p1 makes it invalid.
  std::optional<Model> at(double p1) const {
    Model m = model_;
    set_parameter(m, parameter_, p1);
    if (validate_model(m)) return std::nullopt;
    return at_phase(m, phase_);
  }

  Eval evaluate(const Vec& x, double p1) const {
    Eval e;
    const std::optional<Model> m = at(p1);
    if (!m || stopped()) return e;
    SimOptions o = options_;
    if (!deadline_.never()) o.deadline_ms = deadline_.left_ms();
    e.map = stroboscopic_map(*m, o, periods_, x);
    if (!e.map.ok) return e;
    const int n = static_cast<int>(x.size());
    const Mat I = Mat::Identity(n, n);
    switch (kind_) {
      case BifurcationKind::fold:
        e.g = (e.map.jacobian - I).determinant();
        break;
      case BifurcationKind::period_doubling:
        e.g = (e.map.jacobian + I).determinant();
        break;
      default:
        e.g = signed_clearance(*m, e.map.run) - kGrazingClearance;
    }
    e.ok = std::isfinite(e.g) && e.map.jacobian.allFinite();
    return e;
  }

  // Moves the section to the middle of the longest stretch of the motion from x (at p1) without
  // events, so that no impact or turning point sits on it; returns x moved there.
  Vec clear_section(const Vec& x, double p1) {
    const Eval e = evaluate(x, p1);
    if (!e.ok) return x;
    const double span = periods_ * forcing_period(*at(p1));
    std::vector<double> times = {0.0};
    for (const Event& ev : e.map.run.events) times.push_back(ev.t);
    times.push_back(span);
    std::sort(times.begin(), times.end());
    double longest = -1.0, middle = 0.0;
    for (std::size_t k = 1; k < times.size(); ++k)
      if (times[k] - times[k - 1] > longest) {
        longest = times[k] - times[k - 1];
        middle = 0.5 * (times[k] + times[k - 1]);
      }
    const std::optional<Vec> y = run_from(*at(p1), options_, x, middle);
    if (!y) return x;
    phase_ += middle;
    return *y;
  }

  // The test function's derivative from its values at −h, 0 and +h: central, but for a grazing
  // one-sided on the middle one's side where the three straddle the touching clearance: there
  // the test function has a kink (a square root on the striking side), which a central
  // difference across it would take for a huge slope.
  double slope(double at, double up, double down, double h) const {
    if (kind_ != BifurcationKind::grazing) return (up - down) / (2.0 * h);
    const auto side = [](double g) { return g + kGrazingClearance >= 0.0; };
    const bool up_same = side(up) == side(at), down_same = side(down) == side(at);
    if (up_same && down_same) return (up - down) / (2.0 * h);
    return up_same ? (up - at) / h : (at - down) / h;
  }

  // Newton's method on the augmented system from (x, p1): the converged point, or nothing.
  std::optional<std::pair<Vec, double>> solve(Vec x, double p1) const {
    const int n = static_cast<int>(x.size());
    const double speed = speed_scale(model_);
    for (int it = 0; it < 16; ++it) {
      const Eval e = evaluate(x, p1);
      if (!e.ok) return std::nullopt;
      Vec r(n + 1);
      r.head(n) = orbit_residual(e.map);
      r[n] = e.g;
      if (residual_norm(model_, r.head(n)) <= tol_ && std::abs(e.g) <= 10.0 * tol_)
        return std::make_pair(x, p1);
      Mat A(n + 1, n + 1);
      A.topLeftCorner(n, n) = e.map.jacobian - Mat::Identity(n, n);
      const double h = 1e-6 * std::max(std::abs(p1), std::abs(span_));
      const Eval up = evaluate(x, p1 + h), down = evaluate(x, p1 - h);
      if (!up.ok || !down.ok) return std::nullopt;
      A.block(0, n, n, 1) = (up.map.image - down.map.image) / (2.0 * h);
      A(n, n) = slope(e.g, up.g, down.g, h);
      for (int k = 0; k < n; ++k) {
        Vec moved = x;
        const double hk = 1e-6 * (k % 2 ? speed : 1.0);
        moved[k] += hk;
        const Eval forward = evaluate(moved, p1);
        moved[k] -= 2.0 * hk;
        const Eval backward = evaluate(moved, p1);
        if (!forward.ok || !backward.ok) return std::nullopt;
        A(n, k) = slope(e.g, forward.g, backward.g, hk);
      }
      const Vec dz = A.fullPivLu().solve(-r);
      if (!dz.allFinite()) return std::nullopt;
      x += dz.head(n);
      p1 += dz[n];
    }
    return std::nullopt;
  }

 private:
  Model model_;
  const SimOptions& options_;
  int periods_;
  std::string parameter_;
  BifurcationKind kind_;
  double span_;
  const Deadline& deadline_;
  const std::atomic<bool>* cancel_;
  double tol_;
  double phase_ = 0.0;
};

// A point of the curve with the section state that solves it.
struct Node {
  double value2 = 0.0;
  Vec x;
  double p1 = 0.0;
};

// One walk of the curve in the second parameter from `start` to `target`.
class Walk {
 public:
  Walk(Augmented& system, const Model& model, const FollowSpec& spec, double range,
       const std::function<void(double)>& progress)
      : system_(system), model_(model), spec_(spec), range_(range), progress_(progress) {}

  // Walks to `target`, adding at most `budget` nodes; says how it ended in `why`. The share of
  // the range walked before this walk is `done`.
  std::vector<Node> run(const Node& start, double target, int budget, double done, bool& reached,
                        std::string& why) {
    std::vector<Node> nodes;
    const double span = target - start.value2;
    reached = span == 0.0;
    double ds = span / 16.0;
    const double ds_min = std::abs(span) * 1e-5, ds_max = std::abs(span) / 8.0;
    Node here = start;
    std::optional<Node> before;
    while (!reached) {
      if (static_cast<int>(nodes.size()) >= budget) {
        why = "stopped after the branch's max_points points at " + spec_.parameter2 + " = " +
              number(here.value2) + " (periodic_orbit.continuation.max_points)";
        return nodes;
      }
      if (system_.stopped()) {
        why = "stopped at " + spec_.parameter2 + " = " + number(here.value2) +
              ": cancelled or out of time";
        return nodes;
      }
      const bool last = std::abs(ds) >= std::abs(target - here.value2);
      const double v2 = last ? target : here.value2 + ds;
      std::optional<Node> next = correct(here, before, v2);
      if (!next) {
        ds /= 2.0;
        if (std::abs(ds) >= ds_min) continue;
        why = "lost at " + spec_.parameter2 + " = " + number(here.value2) +
              ": no point of the curve near the next one predicted";
        return nodes;
      }
      before = here;
      here = *next;
      nodes.push_back(here);
      reached = last;
      ds = std::copysign(std::min(ds_max, std::abs(ds) * 1.5), span);
      if (progress_) progress_(done + std::abs(here.value2 - start.value2) / range_);
    }
    why = "reached " + spec_.parameter2 + " = " + number(target);
    return nodes;
  }

 private:
  // The point at v2, predicted by the secant through the last two (or at the last one).
  std::optional<Node> correct(const Node& here, const std::optional<Node>& before, double v2) {
    Vec x = here.x;
    double p1 = here.p1;
    if (before && before->value2 != here.value2) {
      const double s = (v2 - here.value2) / (here.value2 - before->value2);
      x += s * (here.x - before->x);
      p1 += s * (here.p1 - before->p1);
    }
    Model m = model_;
    set_parameter(m, spec_.parameter2, v2);
    if (validate_model(m)) return std::nullopt;
    system_.set_model(m);
    const auto solved = system_.solve(x, p1);
    if (!solved) return std::nullopt;
    return Node{v2, solved->first, solved->second};
  }

  Augmented& system_;
  const Model& model_;
  const FollowSpec& spec_;
  double range_;
  const std::function<void(double)>& progress_;
};

const Bifurcation* first_of_kind(const OrbitBranch& branch, BifurcationKind kind) {
  for (const Bifurcation& b : branch.bifurcations)
    if (b.kind == kind) return &b;
  return nullptr;
}

}  // namespace

std::optional<FieldError> validate_follow(const Model& model, const ContinuationSpec& continuation,
                                          const FollowSpec& spec, const Limits& limits) {
  const std::string field = "periodic_orbit.continuation.";
  if (spec.kind == BifurcationKind::neimark_sacker)
    return FieldError{field + "follow", "expected \"fold\", \"period_doubling\" or \"grazing\""};
  // A mobile limiter's armed state changes along the motion; the walk keeps the scene's own.
  for (std::size_t l = 0; l < model.limiters.size(); ++l)
    if (model.limiters[l].mobile)
      return FieldError{"model.limiters[" + std::to_string(l) + "].mobile",
                        "bifurcation curves are followed with fixed limiters only: the curve's "
                        "section would need the mobile limiter's armed state at its phase"};
  const std::string p2 = field + "parameter2.";
  const std::optional<double> own = get_parameter(model, spec.parameter2);
  if (!own)
    return FieldError{p2 + "parameter",
                      "names no numeric field of this model: \"" + spec.parameter2 + "\""};
  if (spec.parameter2 == continuation.parameter)
    return FieldError{p2 + "parameter", "must differ from the continuation's parameter \"" +
                                            continuation.parameter +
                                            "\": the curve is followed in a second one"};
  for (const auto& [name, v] : {std::pair{"from", spec.from}, std::pair{"to", spec.to}}) {
    if (!std::isfinite(v)) return FieldError{p2 + name, "expected a finite number"};
    Model end = model;
    set_parameter(end, spec.parameter2, v);
    if (auto e = validate_model(end, limits))
      return FieldError{p2 + name, "makes the model invalid: " + e->field + " " + e->message};
  }
  if (!(spec.from < spec.to))
    return FieldError{p2 + "to", "expected a value above parameter2.from"};
  if (*own < spec.from || *own > spec.to)
    return FieldError{p2 + "from",
                      "the scene's own value of " + spec.parameter2 + " (" + number(*own) +
                          ") must lie from parameter2.from to parameter2.to: the curve starts "
                          "there"};
  return std::nullopt;
}

BifurcationCurve follow_bifurcation(const Model& model, const SimOptions& options, int periods,
                                    const ContinuationSpec& continuation, const OrbitBranch& branch,
                                    const FollowSpec& spec,
                                    const std::function<void(double)>& progress,
                                    const std::atomic<bool>* cancel) {
  BifurcationCurve curve;
  curve.kind = spec.kind;
  const std::string kind(bifurcation_kind_name(spec.kind));
  const Bifurcation* b = first_of_kind(branch, spec.kind);
  if (!b) {
    curve.message = "the branch shows no " + kind + " to follow";
    return curve;
  }
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  const double span1 = continuation.to - *get_parameter(model, continuation.parameter);
  Augmented system(model, options, periods, continuation.parameter, spec.kind, span1, deadline,
                   cancel);
  Vec x(2 * model.size());
  for (int i = 0; i < model.size(); ++i) x.segment(2 * i, 2) << b->state[i].phi, b->state[i].dphi;
  x = system.clear_section(x, b->value);
  const auto start = system.solve(x, b->value);
  if (!start) {
    curve.message = "the " + kind + " at " + continuation.parameter + " = " + number(b->value) +
                    " could not be solved for as a point of the curve";
    return curve;
  }
  const Node first{*get_parameter(model, spec.parameter2), start->first, start->second};
  Walk walk(system, model, spec, spec.to - spec.from, progress);
  std::string up_why, down_why;
  const std::vector<Node> up =
      walk.run(first, spec.to, continuation.max_points - 1, 0.0, curve.reached_to, up_why);
  const int left = continuation.max_points - 1 - static_cast<int>(up.size());
  const double up_share = (spec.to - first.value2) / (spec.to - spec.from);
  const std::vector<Node> down =
      walk.run(first, spec.from, left, up_share, curve.reached_from, down_why);
  for (auto it = down.rbegin(); it != down.rend(); ++it)
    curve.points.push_back({it->p1, it->value2});
  curve.points.push_back({first.p1, first.value2});
  for (const Node& n : up) curve.points.push_back({n.p1, n.value2});
  curve.message = "toward parameter2.to: " + up_why + "; toward parameter2.from: " + down_why;
  if (progress) progress(1.0);
  return curve;
}

}  // namespace vibro
