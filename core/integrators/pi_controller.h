// Hairer's PI step-size controller of DOPRI5 and DOP853 (with Lund stabilisation).
#pragma once

#include <algorithm>
#include <cmath>

namespace vibro::integrators {

class PiController {
 public:
  struct Params {
    double expo;  // exponent of the error: 0.2 − 0.75·beta (DOPRI5), 1/8 − 0.2·beta (DOP853)
    double beta;  // Lund stabilisation exponent of the previous error
    double fac1;  // smallest ratio h_new/h
    double fac2;  // largest ratio h_new/h
    double safe;  // safety factor
  };

  explicit constexpr PiController(const Params& p) : p_(p) {}

  // Forgets the error history (a new integration).
  void reset() { err_old_ = 1e-4; }

  // The next step after an accepted step of size h with error err <= 1.
  double accepted(double h, double err) {
    const double fac11 = std::pow(err, p_.expo);
    double fac = fac11 / std::pow(err_old_, p_.beta);
    fac = std::max(1.0 / p_.fac2, std::min(1.0 / p_.fac1, fac / p_.safe));
    err_old_ = std::max(err, 1e-4);
    return h / fac;
  }

  // The retry after a rejected step of size h with error err > 1.
  double rejected(double h, double err) const {
    const double fac11 = std::pow(err, p_.expo);
    return h / std::min(1.0 / p_.fac1, fac11 / p_.safe);
  }

 private:
  Params p_;
  double err_old_ = 1e-4;
};

}  // namespace vibro::integrators
