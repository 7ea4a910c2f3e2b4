#include "core/events/chatter.h"

#include <cmath>
#include <limits>

namespace vibro {

std::optional<ChatterSeries> chatter_series(const Model& model, double t, double theta, int side,
                                            double u, double k, double a_free) {
  if (!(u > 0.0) || !(k > 0.0) || !(k <= 1.0)) return std::nullopt;
  const double press = -side * a_free;  // toward the limiter
  double friction = model.mu() * model.g / model.R * std::cos(theta);
  if (model.friction == FrictionLaw::bilateral) friction = std::abs(friction);
  const double a_away = press + friction;
  const double a_toward = press - friction;
  if (!(a_toward > 0.0) || !(a_away > 0.0)) return std::nullopt;
  // The pellet would stay put at the top of its flight if static friction can hold it.
  if (std::abs(a_free) <= model.mu_static() * model.g / model.R * std::abs(std::cos(theta))) {
    return std::nullopt;
  }
  ChatterSeries c;
  c.r = k * std::sqrt(a_toward / a_away);
  // Near the top the paper law's friction pushes along (a_away < a_toward), and the series
  // need not shrink: summed, it would accumulate before it starts.
  if (!(c.r < 1.0)) return std::nullopt;
  c.t_next = u / a_away + u / std::sqrt(a_away * a_toward);
  c.t_star = t + c.t_next / (1.0 - c.r);
  // r a hair below 1 asks for some 10^17 impacts: counted up to what an int holds.
  const double impacts =
      std::ceil(std::log(std::numeric_limits<double>::epsilon()) / std::log(c.r));
  c.impacts = impacts < std::numeric_limits<int>::max() ? static_cast<int>(impacts)
                                                        : std::numeric_limits<int>::max();
  return c;
}

}  // namespace vibro
