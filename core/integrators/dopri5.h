// Dormand–Prince 5(4) as in Hairer's DOPRI5, with its 4th-order dense output (CONTD5).
#pragma once

#include <string_view>

#include "core/integrators/error_norm.h"
#include "core/integrators/explicit_rk.h"
#include "core/integrators/hermite_dense.h"
#include "core/integrators/ode.h"
#include "core/integrators/pi_controller.h"

namespace vibro::integrators {

// The DOPRI5 tableau for ExplicitRk.
class Dopri5Scheme {
 public:
  static constexpr std::string_view kName = "dopri5";
  static constexpr int kOrder = 5;
  // DOPRI5's defaults: beta = 0.04, expo1 = 0.2 - 0.75·beta, fac1 = 0.2, fac2 = 10, safe = 0.9.
  static constexpr PiController::Params kControl{0.2 - 0.04 * 0.75, 0.04, 0.2, 10.0, 0.9};
  static constexpr double kStiffBound = 3.25;
  static constexpr int kAttemptEvals = 6;  // stages 2..7; stage 7 is f(t + h, y1) (FSAL)
  static constexpr int kCompletionEvals = 0;
  static constexpr int kDenseEvals = 0;

  void resize(int n);
  double attempt(const OdeSystem& sys, double t, const Vec& y, const Vec& k1, double h,
                 const Tolerance& tol, Vec& y1, Vec& k7);
  void complete(const OdeSystem&, double, const Vec&, Vec&) {}
  const Vec& last_stage_y() const { return y6_; }
  const Vec& last_stage_f() const { return k6_; }
  void prepare_dense(const OdeSystem& sys, double t0, const Vec& y0, const Vec& k1, double h,
                     const Vec& y1, const Vec& k7);
  void dense(double theta, Vec& out) const { dense_.eval(theta, out); }

 private:
  Vec k2_, k3_, k4_, k5_, k6_;
  Vec yt_;   // stage argument
  Vec y6_;   // the 6th stage's argument, kept for the stiffness quotient
  Vec err_;  // error estimate
  HermiteDense<1> dense_;
};

extern template class ExplicitRk<Dopri5Scheme>;
using Dopri5 = ExplicitRk<Dopri5Scheme>;

}  // namespace vibro::integrators
