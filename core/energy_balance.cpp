#include "core/energy_balance.h"

#include <algorithm>
#include <cmath>

#include "core/motion.h"

namespace vibro {

EnergyBalance::EnergyBalance(const Model& model, const Vec& y0)
    : model_(model), energy0_(total_energy(y0)), scale_(0.0) {
  for (const Pellet& p : model.pellets)
    scale_ += 0.5 * p.m * model.R * model.R * p.dphi0 * p.dphi0 + 2.0 * p.m * model.g * model.R;
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
