// The dense output of DOPRI5 (CONTD5) and DOP853 (CONTD8), in Hairer's form: the cubic Hermite
// interpolant through (y0, h·f0) and (y1, h·f1), plus θ²(1−θ)² times a correction polynomial whose
// coefficients come from the stages (one for DOPRI5, four for DOP853).
#pragma once

#include <array>

#include "core/integrators/ode.h"

namespace vibro::integrators {

template <int Corrections>
class HermiteDense {
 public:
  void resize(int n) {
    for (Vec& r : r_) r.resize(n);
  }

  // The Hermite part of a step of size h from (y0, f0) to (y1, f1).
  void set_ends(const Vec& y0, const Vec& y1, const Vec& f0, const Vec& f1, double h) {
    const Eigen::Index n = y0.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double ydiff = y1[i] - y0[i];
      const double bspl = h * f0[i] - ydiff;
      r_[0][i] = y0[i];
      r_[1][i] = ydiff;
      r_[2][i] = bspl;
      r_[3][i] = ydiff - h * f1[i] - bspl;
    }
  }

  // The j-th coefficient of the correction polynomial, for the scheme to fill.
  Vec& correction(int j) { return r_[4 + j]; }

  // out = y(t0 + theta·h).
  void eval(double theta, Vec& out) const {
    const double s = theta;
    const double s1 = 1.0 - theta;
    const Eigen::Index n = r_[0].size();
    for (Eigen::Index i = 0; i < n; ++i) {
      // Hairer's nesting alternates θ and 1 − θ: c0 + θ(c1 + (1−θ)(c2 + θ·c3)) for DOP853.
      double conp = r_[3 + Corrections][i];
      for (int j = Corrections - 2; j >= 0; --j) conp = r_[4 + j][i] + (j % 2 == 0 ? s : s1) * conp;
      out[i] = r_[0][i] + s * (r_[1][i] + s1 * (r_[2][i] + s * (r_[3][i] + s1 * conp)));
    }
  }

 private:
  std::array<Vec, 4 + Corrections> r_;
};

}  // namespace vibro::integrators
