#include "core/integrators/initial_step.h"

#include <algorithm>
#include <cmath>

namespace vibro::integrators {

double initial_step(const OdeSystem& sys, double t0, const Vec& y0, const Vec& f0, int order,
                    double h_max, const Tolerance& tol, Vec& y1, Vec& f1) {
  const Eigen::Index n = y0.size();
  // As in HINIT the sums are not divided by n: only ratios of them and a loose 0.01 target matter.
  double dnf = 0.0;
  double dny = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double sk = tol.scale(i, y0[i]);
    dnf += (f0[i] / sk) * (f0[i] / sk);
    const double y = tol.size(i, y0[i]);  // an angle by its place, not its turns
    dny += (y / sk) * (y / sk);
  }
  double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : std::sqrt(dny / dnf) * 0.01;
  h = std::min(h, h_max);

  for (Eigen::Index i = 0; i < n; ++i) y1[i] = y0[i] + h * f0[i];
  sys.rhs(t0 + h, y1, f1);

  double der2 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double sk = tol.scale(i, y0[i]);
    const double d = (f1[i] - f0[i]) / sk;
    der2 += d * d;
  }
  der2 = std::sqrt(der2) / h;

  const double der12 = std::max(std::abs(der2), std::sqrt(dnf));
  const double h1 = der12 <= 1e-15 ? std::max(1e-6, h * 1e-3) : std::pow(0.01 / der12, 1.0 / order);
  const double guess = std::min({100.0 * h, h1, h_max});
  // A NaN from f: any positive step will do, the step itself reports the non-finite value.
  return std::isfinite(guess) && guess > 0.0 ? guess : std::min(1e-6, h_max);
}

}  // namespace vibro::integrators
