#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>

#include "peers/peer_steppers.h"

namespace vibro::bench {
namespace {

class CvodeStepper final : public Stepper {
 public:
  CvodeStepper(CvodeMethod method, const StepperOptions& options)
      : method_(method), options_(options) {
    SUNContext_Create(nullptr, &ctx_);
  }

  ~CvodeStepper() override {
    CVodeFree(&mem_);
    if (nls_) SUNNonlinSolFree(nls_);
    if (ls_) SUNLinSolFree(ls_);
    if (jac_) SUNMatDestroy(jac_);
    if (y_nv_) N_VDestroy(y_nv_);
    if (dky_) N_VDestroy(dky_);
    SUNContext_Free(&ctx_);
  }

  std::string_view name() const override {
    return method_ == CvodeMethod::adams ? "cvode-adams" : "cvode-bdf";
  }

  void start(const OdeSystem& sys, double t0, const Vec& y0) override {
    sys_ = &sys;
    const int n = static_cast<int>(y0.size());
    if (!mem_) create(n);
    std::copy(y0.data(), y0.data() + n, N_VGetArrayPointer(y_nv_));
    add_counters();  // CVodeReInit zeroes CVODE's own counters
    CVodeReInit(mem_, t0, y_nv_);
    t_prev_ = t_ = t0;
    y_ = y0;
  }

  StepStatus step(double t_limit) override {
    CVodeSetStopTime(mem_, t_limit);
    double t_ret = t_;
    const int flag = CVode(mem_, t_limit, y_nv_, &t_ret, CV_ONE_STEP);
    if (flag < 0) {
      return flag == CV_TOO_CLOSE || flag == CV_TOO_MUCH_ACC ? StepStatus::step_underflow
             : flag == CV_RHSFUNC_FAIL                       ? StepStatus::non_finite
                                                             : StepStatus::solver_failure;
    }
    t_prev_ = t_;
    t_ = t_ret;
    const double* v = N_VGetArrayPointer(y_nv_);
    std::copy(v, v + y_.size(), y_.data());
    if (!y_.allFinite()) return StepStatus::non_finite;
    refresh_stats();
    return StepStatus::ok;
  }

  double t_prev() const override { return t_prev_; }
  double t() const override { return t_; }
  const Vec& y() const override { return y_; }

  void dense(double t, Vec& out) const override {
    out.resize(y_.size());
    if (t_ == t_prev_) {
      out = y_;
      return;
    }
    CVodeGetDky(mem_, std::clamp(t, t_prev_, t_), 0, dky_);
    const double* v = N_VGetArrayPointer(dky_);
    std::copy(v, v + out.size(), out.data());
  }

  const StepperStats& stats() const override { return stats_; }

 private:
  void create(int n) {
    y_nv_ = N_VNew_Serial(n, ctx_);
    dky_ = N_VNew_Serial(n, ctx_);
    in_.resize(n);
    out_.resize(n);
    N_VConst(0.0, y_nv_);
    mem_ = CVodeCreate(method_ == CvodeMethod::adams ? CV_ADAMS : CV_BDF, ctx_);
    CVodeInit(mem_, &CvodeStepper::rhs, 0.0, y_nv_);
    CVodeSetUserData(mem_, this);
    CVodeSStolerances(mem_, options_.rtol, options_.atol);
    CVodeSetMaxNumSteps(mem_, -1);  // one step per call; vibro's budget bounds the run
    if (std::isfinite(options_.h_max)) CVodeSetMaxStep(mem_, options_.h_max);
    if (method_ == CvodeMethod::adams) {
      nls_ = SUNNonlinSol_FixedPoint(y_nv_, 0, ctx_);
      CVodeSetNonlinearSolver(mem_, nls_);
    } else {
      jac_ = SUNDenseMatrix(n, n, ctx_);
      ls_ = SUNLinSol_Dense(y_nv_, jac_, ctx_);
      CVodeSetLinearSolver(mem_, ls_, jac_);
      CVodeSetJacFn(mem_, &CvodeStepper::jacobian);
      dfdy_.resize(n, n);
      dfdt_.resize(n);
    }
  }

  // OdeSystem takes Eigen vectors: the state is copied in and the derivative out (n = 3 per
  // pellet, a few nanoseconds next to an evaluation).
  static int rhs(double t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<CvodeStepper*>(user);
    const double* in = N_VGetArrayPointer(y);
    std::copy(in, in + self->in_.size(), self->in_.data());
    self->sys_->rhs(t, self->in_, self->out_);
    std::copy(self->out_.data(), self->out_.data() + self->out_.size(), N_VGetArrayPointer(ydot));
    return self->out_.allFinite() ? 0 : 1;  // a positive flag: recoverable, CVODE cuts the step
  }

  static int jacobian(double t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector,
                      N_Vector) {
    auto* self = static_cast<CvodeStepper*>(user);
    const double* in = N_VGetArrayPointer(y);
    std::copy(in, in + self->in_.size(), self->in_.data());
    self->sys_->jacobian(t, self->in_, self->dfdy_, self->dfdt_);
    // Both column-major.
    std::copy(self->dfdy_.data(), self->dfdy_.data() + self->dfdy_.size(), SUNDenseMatrix_Data(J));
    return 0;
  }

  void add_counters() {
    if (!mem_) return;
    refresh_stats();
    base_ = stats_;
  }

  void refresh_stats() {
    long steps = 0, rhs = 0, fails = 0, jacs = 0, setups = 0;
    CVodeGetNumSteps(mem_, &steps);
    CVodeGetNumRhsEvals(mem_, &rhs);
    CVodeGetNumErrTestFails(mem_, &fails);
    if (method_ == CvodeMethod::bdf) {
      CVodeGetNumJacEvals(mem_, &jacs);
      CVodeGetNumLinSolvSetups(mem_, &setups);
    }
    stats_.steps = base_.steps + steps;
    stats_.rhs_evals = base_.rhs_evals + rhs;
    stats_.rejected = base_.rejected + fails;
    stats_.jac_evals = base_.jac_evals + jacs;
    stats_.lu_decomps = base_.lu_decomps + setups;
  }

  CvodeMethod method_;
  StepperOptions options_;
  SUNContext ctx_ = nullptr;
  void* mem_ = nullptr;
  N_Vector y_nv_ = nullptr, dky_ = nullptr;
  SUNNonlinearSolver nls_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
  SUNMatrix jac_ = nullptr;
  const OdeSystem* sys_ = nullptr;
  double t_prev_ = 0.0, t_ = 0.0;
  Vec y_, in_, out_, dfdt_;
  Mat dfdy_;
  StepperStats stats_, base_;
};

}  // namespace

std::unique_ptr<Stepper> make_cvode(CvodeMethod method, const StepperOptions& options) {
  return std::make_unique<CvodeStepper>(method, options);
}

}  // namespace vibro::bench
