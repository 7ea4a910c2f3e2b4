#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>

#include "peers/forced_pellet_equations.h"
#include "peers/forced_pellet_peer.h"

namespace vibro::bench {
namespace {

struct UserData {
  ForcedPellet* pellet;
  const Model* model;
};

int rhs(double t, N_Vector y, N_Vector ydot, void* user) {
  const auto* u = static_cast<UserData*>(user);
  const double* x = N_VGetArrayPointer(y);
  double* dx = N_VGetArrayPointer(ydot);
  dx[0] = x[1];
  dx[1] = u->pellet->ddphi(t, x[0], x[1]);
  return 0;
}

int roots(double, N_Vector y, double* g, void* user) {
  const double* x = N_VGetArrayPointer(y);
  static_cast<UserData*>(user)->pellet->events(x[0], x[1], g);
  return 0;
}

// ∂f/∂y of the paper law (MODEL.md, "Sliding motion").
int jacobian(double, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
  const auto* u = static_cast<UserData*>(user);
  const double* x = N_VGetArrayPointer(y);
  const Model& m = *u->model;
  const double gR = m.g / m.R, mu = m.mu();
  const int s = u->pellet->direction();
  SM_ELEMENT_D(J, 0, 0) = 0.0;
  SM_ELEMENT_D(J, 0, 1) = 1.0;
  SM_ELEMENT_D(J, 1, 0) = -gR * (std::cos(x[0]) - s * mu * std::sin(x[0]));
  SM_ELEMENT_D(J, 1, 1) = -2.0 * s * mu * x[1];
  return 0;
}

}  // namespace

PeerRun cvode_forced_pellet(const Model& model, double t_end, double rtol, double atol, bool bdf) {
  ForcedPellet pellet(model);
  UserData user{&pellet, &model};
  PeerRun run;
  SUNContext ctx;
  SUNContext_Create(nullptr, &ctx);
  N_Vector y = N_VNew_Serial(2, ctx);
  double* x = N_VGetArrayPointer(y);
  x[0] = model.pellets[0].phi0;
  x[1] = model.pellets[0].dphi0;
  void* mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, ctx);
  CVodeInit(mem, rhs, 0.0, y);
  CVodeSetUserData(mem, &user);
  CVodeSStolerances(mem, rtol, atol);
  CVodeSetMaxNumSteps(mem, -1);
  CVodeRootInit(mem, ForcedPellet::kEvents, roots);
  int directions[ForcedPellet::kEvents] = {-1, -1, -1};  // only falls through zero are events
  CVodeSetRootDirection(mem, directions);
  SUNNonlinearSolver nls = nullptr;
  SUNMatrix J = nullptr;
  SUNLinearSolver ls = nullptr;
  if (bdf) {
    J = SUNDenseMatrix(2, 2, ctx);
    ls = SUNLinSol_Dense(y, J, ctx);
    CVodeSetLinearSolver(mem, ls, J);
    CVodeSetJacFn(mem, jacobian);
  } else {
    nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    CVodeSetNonlinearSolver(mem, nls);
  }
  auto add_counters = [&] {  // CVodeReInit zeroes them
    long steps = 0, evals = 0;
    CVodeGetNumSteps(mem, &steps);
    CVodeGetNumRhsEvals(mem, &evals);
    run.steps += steps;
    run.rhs_evals += evals;
  };
  double t = 0.0;
  while (t < t_end) {
    const int flag = CVode(mem, t_end, y, &t, CV_NORMAL);
    if (flag < 0) {
      run.failure = "CVode failed with flag " + std::to_string(flag);
      break;
    }
    if (flag != CV_ROOT_RETURN) break;
    int found[ForcedPellet::kEvents];
    CVodeGetRootInfo(mem, found);
    const int which = found[0] ? 0 : found[1] ? 1 : 2;
    run.failure = pellet.apply(which, t, x[0], x[1]);
    if (!run.failure.empty()) break;
    if (which > 0) run.impact_times.push_back(t);
    add_counters();
    CVodeReInit(mem, t, y);
  }
  add_counters();
  CVodeFree(&mem);
  if (nls) SUNNonlinSolFree(nls);
  if (ls) SUNLinSolFree(ls);
  if (J) SUNMatDestroy(J);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return run;
}

}  // namespace vibro::bench
