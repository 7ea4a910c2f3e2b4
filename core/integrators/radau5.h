// Radau IIA of order 5 (3 stages) as in Hairer & Wanner's RADAU5: simplified Newton iteration
// with the real/complex splitting of the transformed stage system, Gustafsson's predictive step
// control, RADAU5's error estimate and the collocation polynomial as dense output (CONTR5).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <string_view>

#include "core/integrators/error_norm.h"
#include "core/integrators/stepper.h"

namespace vibro::integrators {

class Radau5 final : public Stepper {
 public:
  explicit Radau5(const StepperOptions& options);

  std::string_view name() const override { return "radau5"; }
  void start(const OdeSystem& sys, double t0, const Vec& y0) override;
  StepStatus step(double t_limit) override;
  double t_prev() const override { return t_prev_; }
  double t() const override { return t_; }
  const Vec& y() const override { return y_; }
  void dense(double t, Vec& out) const override;
  // The collocation polynomial is of order 3 inside a step, where the step's end is of order 5
  // (Hairer & Wanner IV.5): a fresh step from the last step's start to t is as accurate as a
  // step's end. It costs a factorisation and a Newton iteration; the driver asks only at events.
  void precise_state(double t, Vec& out) override;
  const StepperStats& stats() const override { return stats_; }

  // Continues at (t0, y0) with the first step h0, without an initial step guess: the hand-over
  // from another method (auto).
  void resume(const OdeSystem& sys, double t0, const Vec& y0, double h0);

  // Sizes the work arrays for the dimension n ahead of time (no allocation in start() then).
  void reserve(int n);

  // h·‖∂f/∂y‖∞ of the last accepted step: an upper bound of h·ρ. Small values mean an explicit
  // method would be stable with this step size.
  double stiffness_ratio() const { return stiffness_ratio_; }

  // The step size proposed for the next step.
  double step_size() const { return h_; }

 private:
  using CVec = Eigen::VectorXcd;
  using CMat = Eigen::MatrixXcd;

  enum class Newton { converged, slow, diverged, non_finite };

  StepStatus advance(double t_limit);
  void begin(const OdeSystem& sys, double t0, const Vec& y0);
  void update_scale();
  bool decompose(double h);
  Newton newton(double h, int& iterations);
  void solve_stages(double h);
  double estimate_error(double h);
  void accept(double h, double t_new);

  StepperOptions options_;
  Tolerance tol_;  // RADAU5's internal tolerances (see the constructor)
  double fnewt_;   // Newton stopping tolerance

  const OdeSystem* sys_ = nullptr;
  int n_ = -1;
  StepperStats stats_;

  double t_ = 0.0;
  double t_prev_ = 0.0;
  double h_ = 0.0;      // next step to try; 0 before the first start() and after a failure
  double h_old_ = 0.0;  // last accepted step (extrapolation of the starting values)
  double h_lu_ = 0.0;   // step size of the current factorisations; 0: none
  double h_acc_ = 0.0;  // Gustafsson's memory: last accepted step and its error
  double err_acc_ = 0.0;
  double faccon_ = 1.0;  // Newton contraction memory (FACCON)
  double theta_ = 0.0;   // Newton contraction rate of the last iteration
  double hhfac_ = 1.0;   // step factor after a slowly converging Newton iteration
  double jac_norm_ = 0.0;
  double stiffness_ratio_ = 0.0;
  bool first_ = true;       // no step accepted since start(): no extrapolation
  bool reject_ = false;     // the last attempt was rejected
  bool jac_fresh_ = false;  // the Jacobian was evaluated at the current point (CALJAC)
  bool need_jac_ = true;
  bool f_valid_ = false;  // f_ = f(t_, y_) is up to date

  Vec y_, f_, y_new_, scal_;
  Vec y_prev_;                     // the state at t_prev_ (precise_state steps from it)
  std::unique_ptr<Radau5> probe_;  // takes the steps of precise_state, made on first use
  Vec z1_, z2_, z3_;               // stage increments Z = Y_i − y
  Vec w1_, w2_, w3_;               // transformed increments W = T⁻¹Z (F1..F3 in RADAU5)
  Vec tmp_, ftmp_, f2_, err_;
  Vec cont1_, cont2_, cont3_;  // collocation polynomial of the last step about y_ (CONTR5)
  Vec start_fix_;              // h·f(y_prev) − the polynomial's slope there (dense())
  Mat jac_;
  Vec dfdt_;
  Mat e1_;
  CMat e2_;
  CVec crhs_, csol_;
  Eigen::PartialPivLU<Mat> lu1_;
  Eigen::PartialPivLU<CMat> lu2_;
};

}  // namespace vibro::integrators
