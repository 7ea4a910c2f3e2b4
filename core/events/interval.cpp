#include "core/events/interval.h"

#include <cmath>

namespace vibro {
namespace {

bool any_forced(const Model& model, const Body& body) {
  for (int i : body.members)
    if (model.pellets[i].force.active()) return true;
  return false;
}

}  // namespace

MotionInterval::MotionInterval(const Model& model, std::vector<Body> bodies,
                               const std::vector<bool>& armed,
                               const std::vector<Neighbours>& neighbours, double t, const Vec& y,
                               const EventTolerances& tol, bool pass_reversals)
    : model_(model),
      bodies_(std::move(bodies)),
      dynamics_(model, bodies_, y),
      pass_reversals_(pass_reversals) {
  open(armed, neighbours, t, y, tol);
}

void MotionInterval::reopen(std::vector<Body>& bodies, const std::vector<bool>& armed,
                            const std::vector<Neighbours>& neighbours, double t, const Vec& y,
                            const EventTolerances& tol) {
  bodies_.swap(bodies);
  watches_.clear();
  first_integrals_.clear();
  anything_moves_ = false;
  forced_rest_ = false;
  dynamics_.reset(y);
  open(armed, neighbours, t, y, tol);
}

void MotionInterval::open(const std::vector<bool>& armed, const std::vector<Neighbours>& neighbours,
                          double t, const Vec& y, const EventTolerances& tol) {
  const PlaceRadii radii = place_radii(tol, y);
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b)
    add_body_watches(b, armed, y, radii, tol.accel_round_off);
  dydt_.resize(y.size());
  dynamics_.rhs(t, y, dydt_);
  deflate_reversals_from_rest(t, y, dydt_);
  if (pass_reversals_) deflate_limiters_left(t, y, dydt_, radii.on_limiter);
  if (model_.friction != FrictionLaw::paper) add_normal_watches(t, y, dydt_);
  add_gap_watches(neighbours, t, y, dydt_, radii.contact, tol.v_eps);
}

void MotionInterval::add_body_watches(int b, const std::vector<bool>& armed, const Vec& y,
                                      const PlaceRadii& radii, double accel_round_off) {
  const Body& body = bodies_[b];
  const int L = body.leader();
  const bool forced = any_forced(model_, body);
  std::optional<FirstIntegral> fi;
  if (body.mode == Mode::sliding) {
    anything_moves_ = true;
    const bool passes = passes_reversals(body);
    if (!passes) watches_.push_back({WatchKind::reversal, b, L});
    add_limiter_watch(b, armed, y, body.s, radii.on_limiter);
    if (passes) add_limiter_watch(b, armed, y, -body.s, -radii.on_limiter);
    if (model_.friction == FrictionLaw::paper && !forced && body.members.size() == 1 &&
        model_.pellets[L].c == 0.0)
      fi.emplace(model_, body.s, y[phi_index(L)], y[dphi_index(L)]);
  } else if (forced) {
    forced_rest_ = true;
    Watch w{WatchKind::release, b, L};
    w.target = accel_round_off * (1.0 + std::abs(y[phi_index(L)]));
    watches_.push_back(w);
  }
  first_integrals_.push_back(fi);
  for (int k = 1; k < static_cast<int>(body.members.size()); ++k) {
    Watch w{WatchKind::separation, b, L};
    w.split = k;
    watches_.push_back(w);
  }
}

void MotionInterval::add_limiter_watch(int b, const std::vector<bool>& armed, const Vec& y,
                                       int side, double from) {
  const int L = bodies_[b].leader();
  int lim;
  double target;
  if (next_limiter(model_, armed, bodies_[b], y[phi_index(L)], side, from, lim, target))
    watches_.push_back({WatchKind::limiter, b, L, -1, lim, target, side});
}

bool MotionInterval::passes_reversals(const Body& body) const {
  return pass_reversals_ && body.mode == Mode::sliding && body.members.size() == 1 &&
         model_.mu() == 0.0 && model_.mu_static() == 0.0;
}

void MotionInterval::align_directions(const Vec& y) {
  for (Body& body : bodies_) {
    if (!passes_reversals(body)) continue;
    const double v = y[dphi_index(body.leader())];
    if (v != 0.0) body.s = v > 0.0 ? 1 : -1;
  }
}

void MotionInterval::deflate_limiters_left(double t, const Vec& y, const Vec& dydt,
                                           double on_limiter) {
  for (Watch& w : watches_) {
    if (w.kind != WatchKind::limiter || w.side == bodies_[w.body].s ||
        !(std::abs(w.target - y[phi_index(w.pellet)]) <= on_limiter))
      continue;
    deflate(w, model_, bodies_, t, y, -w.side * y[dphi_index(w.pellet)],
            -w.side * dydt[dphi_index(w.pellet)]);
  }
}

void MotionInterval::deflate_reversals_from_rest(double t, const Vec& y, const Vec& dydt) {
  for (Watch& w : watches_) {
    if (w.kind != WatchKind::reversal || y[dphi_index(w.pellet)] != 0.0) continue;
    deflate(w, model_, bodies_, t, y, bodies_[w.body].s * dydt[dphi_index(w.pellet)], 0.0);
  }
}

void MotionInterval::add_normal_watches(double t, const Vec& y, const Vec& dydt) {
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    if (bodies_[b].mode != Mode::sliding) continue;
    const int L = bodies_[b].leader();
    const double phi = y[phi_index(L)], dphi = y[dphi_index(L)];
    const double n = normal_per_mass(model_, phi, dphi);
    const double rate = dphi * (2.0 * model_.R * dydt[dphi_index(L)] - model_.g * std::sin(phi));
    const bool on_root = std::abs(n) <= 1e-12 * (model_.g + model_.R * dphi * dphi);
    Watch w{WatchKind::normal, b, L};
    w.target = (on_root ? rate : n) < 0.0 ? -1.0 : 1.0;
    if (on_root) deflate(w, model_, bodies_, t, y, w.target * rate, 0.0);
    dynamics_.set_normal_side(b, static_cast<int>(w.target));
    watches_.push_back(w);
  }
}

void MotionInterval::add_gap_watches(const std::vector<Neighbours>& neighbours, double t,
                                     const Vec& y, const Vec& dydt, double contact, double v_eps) {
  std::vector<int>& body_of = body_of_;
  body_of.resize(model_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (int i : bodies_[b].members) body_of[i] = static_cast<int>(b);
  for (const Neighbours& nb : neighbours) {
    if (body_of[nb.behind] == body_of[nb.ahead]) continue;
    Watch w{WatchKind::gap, -1, nb.behind, nb.ahead};
    w.target = nb.offset;
    const double gap = y[phi_index(nb.ahead)] - y[phi_index(nb.behind)] + nb.offset;
    if (gap <= contact) {
      // Parting at a speed below round-off is not parting: they start at one speed.
      double rate = y[dphi_index(nb.ahead)] - y[dphi_index(nb.behind)];
      if (std::abs(rate) <= v_eps) rate = 0.0;
      deflate(w, model_, bodies_, t, y, rate,
              dydt[dphi_index(nb.ahead)] - dydt[dphi_index(nb.behind)]);
    }
    watches_.push_back(w);
  }
}

double MotionInterval::first_integral_residual(const Vec& y) const {
  double worst = 0.0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (!first_integrals_[b]) continue;
    const int L = bodies_[b].leader();
    const double r = first_integrals_[b]->residual(y[phi_index(L)], y[dphi_index(L)]);
    if (std::isfinite(r)) worst = std::max(worst, std::abs(r));
  }
  return worst;
}

}  // namespace vibro
