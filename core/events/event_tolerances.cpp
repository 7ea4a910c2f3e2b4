#include "core/events/event_tolerances.h"

#include <algorithm>
#include <limits>

#include "core/model/motion.h"

namespace vibro {

EventTolerances event_tolerances(const Model& model) {
  EventTolerances tol;
  tol.time_scale = time_scale(model);
  tol.chatter_time = 1e-4 * tol.time_scale;
  double v_scale = 1.0 / tol.time_scale;
  for (const Pellet& p : model.pellets) v_scale = std::max(v_scale, std::abs(p.dphi0));
  tol.v_eps = 1e-13 * v_scale;
  tol.v_merge = 1e-9 * v_scale;
  tol.accel_round_off = 4.0 * std::numeric_limits<double>::epsilon() * model.g / model.R;
  double angle_scale = 1.0;
  for (const Pellet& p : model.pellets) angle_scale = std::max(angle_scale, 1.0 + std::abs(p.phi0));
  tol.start_on_limiter *= angle_scale;
  return tol;
}

PlaceRadii place_radii(const EventTolerances& tol, const Vec& y) {
  double scale = 1.0;
  for (int i = 0; phi_index(i) < y.size(); ++i)
    scale = std::max(scale, 1.0 + std::abs(y[phi_index(i)]));
  return {tol.contact_distance * scale, tol.on_limiter * scale, tol.flight_round_off * scale};
}

}  // namespace vibro
