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
                               const EventTolerances& tol)
    : model_(model), bodies_(std::move(bodies)), dynamics_(model, bodies_, y) {
  const PlaceRadii radii = place_radii(tol, y);
  const bool paper = model.friction == FrictionLaw::paper;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    const Body& body = bodies_[b];
    const int L = body.leader();
    const bool forced = any_forced(model, body);
    std::optional<FirstIntegral> fi;
    if (body.mode == Mode::sliding) {
      anything_moves_ = true;
      watches_.push_back({WatchKind::reversal, b, L});
      int lim;
      double target;
      if (next_limiter(model, armed, body, y[phi_index(L)], body.s, radii.on_limiter, lim,
                       target)) {
        watches_.push_back({WatchKind::limiter, b, L, -1, lim, target});
      }
      if (paper && !forced && body.members.size() == 1) {
        fi.emplace(model, body.s, y[phi_index(L)], y[dphi_index(L)]);
      }
    } else if (forced) {
      forced_rest_ = true;
      watches_.push_back({WatchKind::release, b, L});
    }
    first_integrals_.push_back(fi);
    for (int k = 1; k < static_cast<int>(body.members.size()); ++k) {
      Watch w{WatchKind::separation, b, L};
      w.split = k;
      watches_.push_back(w);
    }
  }
  // A body that starts from rest starts on its reversal watch's root: watched in its deflated form,
  // which starts at the acceleration s·φ̈ > 0, a turn back within the first step is found.
  Vec dydt(y.size());
  dynamics_.rhs(t, y, dydt);
  for (Watch& w : watches_) {
    if (w.kind != WatchKind::reversal || y[dphi_index(w.pellet)] != 0.0) continue;
    deflate(w, model, bodies_, t, y, bodies_[w.body].s * dydt[dphi_index(w.pellet)], 0.0);
  }
  // The bilateral law's kink: the normal force's sign, watched from the side it starts on, or,
  // starting on its root (the kink just passed), from the side it moves to.
  if (!paper) {
    for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
      if (bodies_[b].mode != Mode::sliding) continue;
      const int L = bodies_[b].leader();
      const double phi = y[phi_index(L)], dphi = y[dphi_index(L)];
      const double n = normal_per_mass(model, phi, dphi);
      const double rate = dphi * (2.0 * model.R * dydt[dphi_index(L)] - model.g * std::sin(phi));
      const bool on_root = std::abs(n) <= 1e-12 * (model.g + model.R * dphi * dphi);
      Watch w{WatchKind::normal, b, L};
      w.target = (on_root ? rate : n) < 0.0 ? -1.0 : 1.0;
      if (on_root) deflate(w, model, bodies_, t, y, w.target * rate, 0.0);
      dynamics_.set_normal_side(b, static_cast<int>(w.target));
      watches_.push_back(w);
    }
  }
  // Gaps between neighbours in different bodies.
  std::vector<int> body_of(model.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (int i : bodies_[b].members) body_of[i] = static_cast<int>(b);
  for (const Neighbours& nb : neighbours) {
    if (body_of[nb.behind] == body_of[nb.ahead]) continue;
    Watch w{WatchKind::gap, -1, nb.behind, nb.ahead};
    w.target = nb.offset;
    const double gap = y[phi_index(nb.ahead)] - y[phi_index(nb.behind)] + nb.offset;
    if (gap <= radii.contact) {
      // Parting at a speed below round-off is not parting: they start at one speed.
      double rate = y[dphi_index(nb.ahead)] - y[dphi_index(nb.behind)];
      if (std::abs(rate) <= tol.v_eps) rate = 0.0;
      deflate(w, model, bodies_, t, y, rate,
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
