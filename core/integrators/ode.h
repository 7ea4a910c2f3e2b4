// The seam between the model and the integrators: a smooth first-order system y' = f(t, y).
// The simulator builds one per motion segment (between two events), so f is smooth inside it.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <span>

namespace vibro {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int dimension() const = 0;
  // dydt = f(t, y); dydt is already sized to dimension().
  virtual void rhs(double t, const Vec& y, Vec& dydt) const = 0;
  // dfdy = ∂f/∂y (n×n) and dfdt = ∂f/∂t (n), both exact; implicit methods use them.
  virtual void jacobian(double t, const Vec& y, Mat& dfdy, Vec& dfdt) const = 0;
  // 2π for a component that is an angle, 0 for the others. The integrators hold an angle to rtol
  // times its distance from the nearest whole turn, not times the turns that brought it there: a
  // pellet swinging 0.01 rad about the bottom after 30 turns (φ ≈ 188.5 rad) was held to
  // 1.9e-8 rad at rtol 1e-10, and its turns came 9e-9 s late where the same swing before any
  // turn came 7e-11 s late.
  virtual double period(int /*component*/) const { return 0.0; }
  // The solution through (t0, y0) as normalized Taylor coefficients, y_i^(k)(t0)/k! for
  // k = 0..order, written component by component (order + 1 each) into out, which holds
  // dimension()·(order + 1): a Taylor method's step (core/integrators/taylor.h). False for a
  // system that does not compute them.
  virtual bool taylor_coefficients(double /*t0*/, const Vec& /*y0*/, int /*order*/,
                                   std::span<double> /*out*/) const {
    return false;
  }
  // True where taylor_coefficients computes them (`auto` runs the Taylor method only there).
  virtual bool has_taylor_coefficients() const { return false; }
  // How much faster than the solution itself moves a disturbance of it can decay at (t, y), an
  // estimate from above where the system knows one: a ratio of rates, large only where the
  // equations may be stiff. `auto` leaves Taylor to probe for stiffness only above
  // AutoSwitch::kStiffnessHint. Infinity by default (unknown: always probe).
  virtual double stiffness_hint(double /*t*/, const Vec& /*y*/) const { return INFINITY; }
};

}  // namespace vibro
