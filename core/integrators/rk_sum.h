// The weighted sums of explicit Runge–Kutta stages, written once: each call expands (by a fold
// expression) into a single loop over the components with the weights as constants, as fast as
// the hand-written loops of Hairer's codes and with no temporaries.
#pragma once

#include "core/integrators/ode.h"

namespace vibro::integrators {

// One term a·k of a Runge–Kutta sum.
struct Term {
  double a;
  const Vec& k;
};

// out = y + h·Σ a_j·k_j: a stage argument or a solution.
template <class... Terms>
inline void rk_sum(Vec& out, const Vec& y, double h, const Terms&... terms) {
  const Eigen::Index n = y.size();
  for (Eigen::Index i = 0; i < n; ++i) out[i] = y[i] + h * (... + (terms.a * terms.k[i]));
}

// out = h·Σ a_j·k_j: a coefficient of a dense-output polynomial.
template <class... Terms>
inline void rk_sum(Vec& out, double h, const Terms&... terms) {
  const Eigen::Index n = out.size();
  for (Eigen::Index i = 0; i < n; ++i) out[i] = h * (... + (terms.a * terms.k[i]));
}

}  // namespace vibro::integrators
