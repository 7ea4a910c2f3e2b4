// A Taylor-series method: each step is the solution's own series at the step's start, of an
// order set by the tolerance, computed by the system's jets (OdeSystem::taylor_coefficients).
// Order and step size follow Jorba & Zou (Exp. Math. 14(1), 2005), as heyoka does, with the
// order raised by kOrderAboveJorbaZou: no error estimate and no rejected steps. The step is its
// polynomials (StepView::polynomials), so the dense output is the polynomial itself, as accurate as
// the step's end. Its stats count the jets as one right-hand-side evaluation per step.
#pragma once

#include <string_view>
#include <vector>

#include "core/integrators/error_norm.h"
#include "core/integrators/stepper.h"

namespace vibro::integrators {

class Taylor final : public Stepper {
 public:
  // Above this order the series is not served to the event search (kMaxPolynomialDegree); the
  // tolerances allowed (rtol >= 1e-14) ask for 21 at most.
  static constexpr int kMaxOrder = 30;

  explicit Taylor(const StepperOptions& options);

  // Jorba and Zou's order p_JZ = ⌈−½ ln ε + 1⌉ for the tolerance ε, the cheapest where a step
  // costs as its jets, ∝ p²: the series' terms beyond p_JZ fall below ε·e^−2 of the state over
  // a step of ρ/e², ρ the radius its last coefficients show.
  static int jorba_zou_order(double rtol);

  // Here a step costs more than its jets (the event search, the step's size, the driver: about
  // four fifths of a step at p_JZ), so fewer, longer steps of a higher order cost less. Measured
  // by the instructions of whole runs (bench/auto_cost.sh's Taylor rows, the eleven non-stiff
  // presets at rtol 1e-6 to 1e-14; docs/PERFORMANCE.md "The order"): +3 cuts their geometric
  // mean by 5 % (1e-14) to 17 % (1e-6) and the steps by a third; +5 cuts no more and costs the
  // worst case more. Only runs whose steps end at events anyway pay (mass-ratio +4 to 6 %,
  // chatter +2 to 3 %).
  static constexpr int kOrderAboveJorbaZou = 3;

  // The order: p_JZ + kOrderAboveJorbaZou.
  static int order_for(double rtol);

  // The step over the radius ρ for the order p: exp(−0.7/(p − 1))·e^(−2·p_JZ/p), the step at
  // which the last term (h/ρ)^p is Jorba and Zou's e^(−2·p_JZ), with their safety factor.
  static double safety_for(double rtol, int order);

  std::string_view name() const override { return "taylor"; }
  // A system without jets fails its first step (StepStatus::solver_failure).
  void start(const OdeSystem& sys, double t0, const Vec& y0) override;
  // No step size is carried from one interval to the next: each step's size is its own series'.
  void continue_smoothly(const OdeSystem& sys, double t0, const Vec& y0) override {
    start(sys, t0, y0);
  }
  StepStatus step(double t_limit) override;
  // A Taylor step is its polynomial: it passes t_land.
  StepStatus step_landing(double t_limit, double /*t_land*/) override { return step(t_limit); }
  const Vec& y() const override { return y_; }
  double t_prev() const override { return t_prev_; }
  double t() const override { return t_; }
  void dense(double t, Vec& out) const override;
  const StepPolynomials* polynomials() const override { return stepped_ ? &poly_ : nullptr; }
  const StepperStats& stats() const override { return stats_; }

  int order() const { return order_; }

 private:
  // Jorba and Zou's step: safety_for·min(ρ_{p−1}, ρ_p), ρ_k = min_i (w_i/|c_i[k]|)^(1/k) with w_i
  // the component's tolerance scale over rtol (relative to its size, atol/rtol at least).
  // Infinite where the series stops (a body at rest).
  double step_size();

  StepperOptions options_;
  Tolerance tol_;
  int order_;
  double safety_;        // safety_for(rtol, order_)
  double exponents_[2];  // 1/(p − 1), 1/p: the radii's powers, once per order
  const OdeSystem* sys_ = nullptr;
  int n_ = 0;
  double t_ = 0.0, t_prev_ = 0.0;
  bool stepped_ = false;  // a step since start(): the polynomials describe [t_prev_, t_]
  Vec y_, y_next_;
  Vec scale_;  // step_size's tolerance scale per component
  // The last dense state of this step and its time: an event's instant is asked for several times
  // (the recheck, the grazes, the driver, the polisher), each the same evaluation.
  mutable double dense_t_ = 0.0;
  mutable bool dense_kept_ = false;
  mutable Vec dense_y_;
  std::vector<double> coefficients_;  // the last step's series, (order_ + 1) per component
  StepPolynomials poly_;
  StepperStats stats_;
};

}  // namespace vibro::integrators
