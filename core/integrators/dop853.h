// Hairer's DOP853: explicit Runge–Kutta of order 8 with the combined 5th/3rd-order error estimate
// and the 7th-order dense output (three extra stages, CONTD8).
#pragma once

#include <array>
#include <string_view>

#include "core/integrators/error_norm.h"
#include "core/integrators/explicit_rk.h"
#include "core/integrators/hermite_dense.h"
#include "core/integrators/ode.h"
#include "core/integrators/pi_controller.h"

namespace vibro::integrators {

// The DOP853 tableau for ExplicitRk.
class Dop853Scheme {
 public:
  static constexpr std::string_view kName = "dop853";
  static constexpr int kOrder = 8;
  // DOP853's defaults: beta = 0, expo1 = 1/8, fac1 = 0.333, fac2 = 6, safe = 0.9.
  static constexpr PiController::Params kControl{1.0 / 8.0, 0.0, 0.333, 6.0, 0.9};
  static constexpr double kStiffBound = 6.1;
  static constexpr int kAttemptEvals = 11;    // stages 2..12
  static constexpr int kCompletionEvals = 1;  // f(t + h, y1), the next step's first stage
  static constexpr int kDenseEvals = 3;       // stages 14..16

  void resize(int n);
  double attempt(const OdeSystem& sys, double t, const Vec& y, const Vec& k1, double h,
                 const Tolerance& tol, Vec& y1, Vec& k13);
  void complete(const OdeSystem& sys, double t1, const Vec& y1, Vec& k13) { sys.rhs(t1, y1, k13); }
  const Vec& last_stage_y() const { return y12_; }
  const Vec& last_stage_f() const { return k_[12]; }
  void prepare_dense(const OdeSystem& sys, double t0, const Vec& y0, const Vec& k1, double h,
                     const Vec& y1, const Vec& k13);
  void dense(double theta, Vec& out) const { dense_.eval(theta, out); }

 private:
  std::array<Vec, 17> k_;  // k_[s] is stage s (1-based as in the paper; k1 and k13 live outside)
  Vec yt_;                 // stage argument
  Vec y12_;                // the 12th stage's argument, kept for the stiffness quotient
  HermiteDense<4> dense_;
};

extern template class ExplicitRk<Dop853Scheme>;
using Dop853 = ExplicitRk<Dop853Scheme>;

}  // namespace vibro::integrators
