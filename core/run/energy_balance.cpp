#include "core/run/energy_balance.h"

#include <algorithm>
#include <cmath>

#include "core/model/motion.h"

namespace vibro {

EnergyBalance::EnergyBalance(const Model& model, const Vec& y0)
    : model_(model), energy0_(total_energy(y0)), scale_(0.0) {
  double forcing = 0.0;  // the work the forces can do over a turn, J
  for (const Pellet& p : model.pellets) {
    scale_ += 0.5 * p.m * model.R * model.R * p.dphi0 * p.dphi0 + 2.0 * p.m * model.g * model.R;
    forcing += kTwoPi * std::abs(p.force.F0) * model.R;
  }
  // Where gravity does not set the scene's scales, the forces' work does (the defect of a
  // forced pellet on a horizontal circle was taken relative to 1e-300 J).
  if (!gravity_sets_time_scale(model)) scale_ = std::max(scale_, forcing);
  scale_ = std::max(scale_, 1e-300);
}

double EnergyBalance::total_energy(const Vec& y) const {
  double E = 0.0;
  for (int i = 0; i < model_.size(); ++i) E += energy(model_, i, y[phi_index(i)], y[dphi_index(i)]);
  return E;
}

void EnergyBalance::check(const Vec& y) {
  double work = 0.0;
  for (int i = 0; i < model_.size(); ++i) work += y[work_index(i)];
  const double defect = total_energy(y) - energy0_ - work - kinetic_change_;
  scale_ = std::max(scale_, std::abs(work));
  if (std::isfinite(defect)) max_defect_ = std::max(max_defect_, std::abs(defect) / scale_);
}

}  // namespace vibro
