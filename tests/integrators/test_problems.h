// Test problems with known solutions (or known behaviour) and a driver loop for the integrators.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "core/integrators/ode.h"
#include "core/integrators/stepper.h"

namespace vibro::testing {

// y0' = y1, y1' = -y0 with y(0) = (1, 0): y = (cos t, -sin t).
class Oscillator final : public OdeSystem {
 public:
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -y[0];
  }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy << 0.0, 1.0, -1.0, 0.0;
    dfdt.setZero();
  }
  static Vec initial() { return Vec::Unit(2, 0); }
  static Vec exact(double t) { return Vec{{std::cos(t), -std::sin(t)}}; }
};

// y' = -2ty with y(0) = 1: y = exp(-t²). Non-autonomous.
class Gaussian final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double t, const Vec& y, Vec& dydt) const override { dydt[0] = -2.0 * t * y[0]; }
  void jacobian(double t, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = -2.0 * t;
    dfdt[0] = -2.0 * y[0];
  }
  static Vec initial() { return Vec::Ones(1); }
  static Vec exact(double t) { return Vec::Constant(1, std::exp(-t * t)); }
};

// y0' = −y1 + y0·(1 − r²), y1' = y0 + y1·(1 − r²): a nonlinear system whose solutions spiral onto
// the unit circle; from radius 1/2 at t = 0, r = (1 + 3·exp(−2t))^(−1/2) and the angle is t.
class LimitCycle final : public OdeSystem {
 public:
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    const double g = 1.0 - y[0] * y[0] - y[1] * y[1];
    dydt[0] = -y[1] + y[0] * g;
    dydt[1] = y[0] + y[1] * g;
  }
  void jacobian(double, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    const double x = y[0];
    const double v = y[1];
    dfdy << 1.0 - 3.0 * x * x - v * v, -1.0 - 2.0 * x * v,  //
        1.0 - 2.0 * x * v, 1.0 - x * x - 3.0 * v * v;
    dfdt.setZero();
  }
  static Vec exact(double t) {
    const double r = 1.0 / std::sqrt(1.0 + 3.0 * std::exp(-2.0 * t));
    return Vec{{r * std::cos(t), r * std::sin(t)}};
  }
};

// Van der Pol in Hairer's scaling, y0' = y1, y1' = ((1 − y0²)·y1 − y0)/eps: eps = 1e-6 is
// mu = 1e3 with time measured in units of mu (one relaxation period ≈ 1.614).
class VanDerPol final : public OdeSystem {
 public:
  explicit VanDerPol(double eps) : eps_(eps) {}
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    dydt[0] = y[1];
    dydt[1] = ((1.0 - y[0] * y[0]) * y[1] - y[0]) / eps_;
  }
  void jacobian(double, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy << 0.0, 1.0, (-2.0 * y[0] * y[1] - 1.0) / eps_, (1.0 - y[0] * y[0]) / eps_;
    dfdt.setZero();
  }
  static Vec initial() { return Vec{{2.0, 0.0}}; }
  // y(2) for eps = 1e-6 (y(2000) of the unscaled mu = 1e3 problem, y1 scaled by mu).
  static Vec reference_at_2() { return Vec{{1.706167732170469, -0.8928097010248125}}; }

 private:
  double eps_;
};

// Robertson's chemical kinetics, the classic stiff test.
class Robertson final : public OdeSystem {
 public:
  int dimension() const override { return 3; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    dydt[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
    dydt[2] = 3e7 * y[1] * y[1];
    dydt[1] = -dydt[0] - dydt[2];
  }
  void jacobian(double, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy << -0.04, 1e4 * y[2], 1e4 * y[1],            //
        0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1],  //
        0.0, 6e7 * y[1], 0.0;
    dfdt.setZero();
  }
  static Vec initial() { return Vec{{1.0, 0.0, 0.0}}; }
};

// y' = −lambda(t)·(y − cos t) − sin t, y(0) = 1: y = cos t for any lambda. lambda falls smoothly
// from 1e4 (stiff) to 1 (non-stiff) around t = 2.
class StiffThenCalm final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  static double lambda(double t) { return 1.0 + 0.5e4 * (1.0 - std::tanh(5.0 * (t - 2.0))); }
  void rhs(double t, const Vec& y, Vec& dydt) const override {
    dydt[0] = -lambda(t) * (y[0] - std::cos(t)) - std::sin(t);
  }
  void jacobian(double t, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = -lambda(t);
    const double s = 1.0 / std::cosh(5.0 * (t - 2.0));
    const double dlambda = -0.5e4 * 5.0 * s * s;
    dfdt[0] = -dlambda * (y[0] - std::cos(t)) - lambda(t) * std::sin(t) - std::cos(t);
  }
  static Vec initial() { return Vec::Ones(1); }
  static Vec exact(double t) { return Vec::Constant(1, std::cos(t)); }
};

// y' = y², y(0) = 1: y = 1/(1 − t) blows up at t = 1.
class BlowUp final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt[0] = y[0] * y[0]; }
  void jacobian(double, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = 2.0 * y[0];
    dfdt[0] = 0.0;
  }
};

// y' = −y, but f is NaN for t > t_bad.
class NanAfter final : public OdeSystem {
 public:
  explicit NanAfter(double t_bad) : t_bad_(t_bad) {}
  int dimension() const override { return 1; }
  void rhs(double t, const Vec& y, Vec& dydt) const override {
    dydt[0] = t > t_bad_ ? std::numeric_limits<double>::quiet_NaN() : -y[0];
  }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = -1.0;
    dfdt[0] = 0.0;
  }

 private:
  double t_bad_;
};

struct RunResult {
  StepStatus status = StepStatus::ok;
  long steps = 0;  // accepted steps of this run
};

// Steps from where the stepper stands to t_end; on_step sees the stepper after each step.
inline RunResult run_to(Stepper& s, double t_end, long max_steps = 10'000'000,
                        const std::function<void(const Stepper&)>& on_step = {}) {
  RunResult run;
  while (s.t() < t_end && run.steps < max_steps) {
    run.status = s.step(t_end);
    if (run.status != StepStatus::ok) break;
    ++run.steps;
    if (on_step) on_step(s);
  }
  return run;
}

// Options that make every step exactly h: tolerances too loose to reject, h_max = h (slightly
// stretched so that accumulated round-off in t does not split the last step).
inline StepperOptions fixed_step(double h) {
  StepperOptions o;
  o.rtol = 1.0;
  o.atol = 1.0;
  o.h_max = h * (1.0 + 1e-9);
  return o;
}

inline const std::vector<Method>& all_methods() {
  static const std::vector<Method> m{Method::dopri5, Method::dop853, Method::radau5,
                                     Method::automatic};
  return m;
}

}  // namespace vibro::testing
