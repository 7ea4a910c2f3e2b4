#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/external/eigen/eigen.hpp>
#include <cmath>
#include <stdexcept>

#include "peers/peer_steppers.h"

namespace vibro::bench {
namespace {

namespace odeint = boost::numeric::odeint;

using Dense = odeint::result_of::make_dense_output<
    odeint::runge_kutta_dopri5<Vec, double, Vec, double, odeint::vector_space_algebra>>::type;

class OdeintDopri5Stepper final : public Stepper {
 public:
  explicit OdeintDopri5Stepper(const StepperOptions& options)
      : options_(options),
        dense_(odeint::make_dense_output(
            options.atol, options.rtol,
            odeint::runge_kutta_dopri5<Vec, double, Vec, double, odeint::vector_space_algebra>())) {
  }

  std::string_view name() const override { return "odeint-dopri5"; }

  void start(const OdeSystem& sys, double t0, const Vec& y0) override {
    sys_ = &sys;
    // No step-size hint on the first start: odeint asks the caller for dt0. A small one, that
    // the controller grows within a few steps (odeint has no HINIT).
    const double dt0 = h_ > 0.0 ? h_ : 1e-4;
    dense_.initialize(y0, t0, dt0);
    t_prev_ = t0;
  }

  StepStatus step(double t_limit) override {
    auto f = [this](const Vec& x, Vec& dxdt, double t) {
      ++stats_.rhs_evals;
      sys_->rhs(t, x, dxdt);
    };
    // As odeint's own integrate_adaptive ends at end_time: a step that would pass the limit is
    // re-initialised to land on it.
    if (dense_.current_time() + dense_.current_time_step() > t_limit) {
      h_ = dense_.current_time_step();
      dense_.initialize(Vec(dense_.current_state()), dense_.current_time(),
                        t_limit - dense_.current_time());
    }
    try {
      const auto span = dense_.do_step(f);
      t_prev_ = span.first;
    } catch (const std::runtime_error&) {  // odeint gives up after 500 rejections in a row
      return StepStatus::step_underflow;
    }
    if (!dense_.current_state().allFinite()) return StepStatus::non_finite;
    ++stats_.steps;
    h_ = dense_.current_time_step();
    return StepStatus::ok;
  }

  double t_prev() const override { return t_prev_; }
  double t() const override { return dense_.current_time(); }
  const Vec& y() const override { return dense_.current_state(); }
  void dense(double t, Vec& out) const override {
    out.resize(dense_.current_state().size());
    dense_.calc_state(t, out);
  }
  const StepperStats& stats() const override { return stats_; }

 private:
  StepperOptions options_;
  Dense dense_;
  const OdeSystem* sys_ = nullptr;
  double t_prev_ = 0.0;
  double h_ = 0.0;
  StepperStats stats_;
};

}  // namespace

std::unique_ptr<Stepper> make_odeint_dopri5(const StepperOptions& options) {
  return std::make_unique<OdeintDopri5Stepper>(options);
}

}  // namespace vibro::bench
