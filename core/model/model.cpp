#include "core/model/model.h"

#include <algorithm>
#include <numbers>

namespace vibro {

bool Limiter::acts_on(int pellet) const {
  return pellets.empty() || std::find(pellets.begin(), pellets.end(), pellet) != pellets.end();
}

bool Model::damped() const {
  return std::any_of(pellets.begin(), pellets.end(), [](const Pellet& p) { return p.c != 0.0; });
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

namespace {

// The longest time of what moves the pellets besides gravity, s; 0 if nothing does.
double motion_time(const Model& model) {
  double motion = 0.0;
  for (const Pellet& p : model.pellets) {
    if (p.dphi0 != 0.0) motion = std::max(motion, 1.0 / std::abs(p.dphi0));
    if (!p.force.active()) continue;
    motion = std::max(motion, std::sqrt(p.m * model.R / std::abs(p.force.F0)));
    if (p.force.Omega != 0.0) motion = std::max(motion, kTwoPi / std::abs(p.force.Omega));
  }
  return std::isfinite(motion) ? motion : 0.0;
}

}  // namespace

bool gravity_sets_time_scale(const Model& model) {
  const double gravity = std::sqrt(model.R / model.g);  // +inf for g = 0
  const double motion = motion_time(model);
  return std::isfinite(gravity) && gravity > 0.0 && !(motion > 0.0 && gravity > 1e3 * motion);
}

double time_scale(const Model& model) {
  if (gravity_sets_time_scale(model)) return std::sqrt(model.R / model.g);
  const double motion = motion_time(model);
  return motion > 0.0 ? motion : 1.0;
}

double speed_scale(const Model& model) {
  return gravity_sets_time_scale(model) ? std::sqrt(model.g / model.R) : 1.0 / time_scale(model);
}

double wrap_angle(double phi) {
  double w = std::remainder(phi, kTwoPi);  // in [−π, π]
  if (w <= -std::numbers::pi) w += kTwoPi;
  return w;
}

}  // namespace vibro
