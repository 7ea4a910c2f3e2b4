// Step-size rules common to all methods: reaching t_limit without a sliver step, h_max, and the
// round-off floor below which no step can make progress.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibro::integrators {

struct StepFit {
  double h;        // the step to attempt
  bool lands;      // the step ends exactly at t_limit
  bool shortened;  // h is below the proposal (and h_max) only to fit t_limit
};

// Fits the proposed step h into [t, t_limit] and h_max. Like DOPRI5 the step is stretched by up to
// 1% to land on t_limit (unless that would exceed h_max); when the rest is shorter than two steps
// it is split evenly, so that no sliver step is left before t_limit.
inline StepFit fit_step(double h, double t, double t_limit, double h_max) {
  h = std::min(h, h_max);
  const double rest = t_limit - t;
  if (rest <= h || (rest <= 1.01 * h && rest <= h_max)) return {rest, true, rest < h};
  if (rest < 2.0 * h) return {0.5 * rest, false, true};
  return {h, false, false};
}

// The step h cannot move t by more than round-off (DOPRI5: 0.1·|h| <= |x|·uround).
inline bool step_underflows(double h, double t) {
  return !(h > 10.0 * std::numeric_limits<double>::epsilon() * std::abs(t)) ||
         h < std::numeric_limits<double>::min();
}

}  // namespace vibro::integrators
