// Hairer's weighted RMS norm of local error estimates, shared by all the integrators.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/integrators/ode.h"

namespace vibro::integrators {

// Per-component error scale sc_i = atol + rtol·max(|y0_i|, |y1_i|) (DOPRI5, DOP853, RADAU5),
// where an angle's size is its distance from the nearest whole turn (OdeSystem::period).
struct Tolerance {
  // No step holds an angle closer than its own round-off: the error it is held to never falls
  // below ten ulps of the angle as it is (a force swinging a pellet to 2e23 rad stalled the
  // steps at 8e-6 s when held to rtol·π).
  static constexpr double kRoundOff = 10.0 * std::numeric_limits<double>::epsilon();

  double atol = 0.0;
  double rtol = 0.0;
  Vec period;  // per component, OdeSystem::period

  // Called as a system starts: its components' periods.
  void take_periods(const OdeSystem& sys) {
    period.resize(sys.dimension());
    for (Eigen::Index i = 0; i < period.size(); ++i) period[i] = sys.period(static_cast<int>(i));
  }
  double size(Eigen::Index i, double y) const {
    const double p = period[i];
    return std::abs(p > 0.0 ? y - p * std::nearbyint(y / p) : y);
  }
  double scale(Eigen::Index i, double y0, double y1) const {
    const double s = atol + rtol * std::max(size(i, y0), size(i, y1));
    return period[i] > 0.0 ? std::max(s, kRoundOff * std::max(std::abs(y0), std::abs(y1))) : s;
  }
  double scale(Eigen::Index i, double y) const { return scale(i, y, y); }
};

// sqrt(mean((e_i / sc_i)²)): 1 is the largest acceptable local error.
inline double rms_norm(const Vec& e, const Vec& y0, const Vec& y1, const Tolerance& tol) {
  const Eigen::Index n = e.size();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = e[i] / tol.scale(i, y0[i], y1[i]);
    sum += r * r;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

inline bool all_finite(const Vec& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace vibro::integrators
