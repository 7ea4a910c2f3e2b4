#include "core/model.h"

#include <algorithm>
#include <numbers>

namespace vibro {

bool Limiter::acts_on(int pellet) const {
  return pellets.empty() || std::find(pellets.begin(), pellets.end(), pellet) != pellets.end();
}

double free_acceleration(const Model& model, int i, double t, double phi) {
  const Pellet& p = model.pellets[i];
  return p.force.at(t) / (p.m * model.R) - model.g / model.R * std::sin(phi);
}

double stick_capacity(const Model& model, double phi) {
  return model.mu_static() * model.g / model.R * std::abs(std::cos(phi));
}

double energy(const Model& model, int i, double phi, double dphi) {
  const double m = model.pellets[i].m;
  return 0.5 * m * model.R * model.R * dphi * dphi - m * model.g * model.R * std::cos(phi);
}

double wrap_angle(double phi) {
  double w = std::remainder(phi, kTwoPi);  // in [−π, π]
  if (w <= -std::numbers::pi) w += kTwoPi;
  return w;
}

}  // namespace vibro
