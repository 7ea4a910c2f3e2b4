#include "core/model/first_integral.h"

#include <cmath>

namespace vibro {

FirstIntegral::FirstIntegral(const Model& model, int s, double phi, double dphi)
    : a_(model.g / (model.R * std::cos(model.alpha0))),
      mu_(model.mu()),
      alpha0_(model.alpha0),
      s_(s >= 0 ? 1 : -1) {
  C_ = (dphi * dphi - particular(phi)) / std::exp(-2.0 * s_ * mu_ * phi);
  scale_ = dphi * dphi + 2.0 * a_;
}

double FirstIntegral::particular(double phi) const {
  const double x = phi + s_ * alpha0_;
  return 2.0 * a_ / (1.0 + 4.0 * mu_ * mu_) * (std::cos(x) - 2.0 * s_ * mu_ * std::sin(x));
}

double FirstIntegral::dphi_squared(double phi) const {
  return particular(phi) + C_ * std::exp(-2.0 * s_ * mu_ * phi);
}

double FirstIntegral::residual(double phi, double dphi) const {
  return (dphi * dphi - dphi_squared(phi)) / scale_;
}

}  // namespace vibro
