// The seam between the model and the integrators: a smooth first-order system y' = f(t, y).
// The simulator builds one per motion segment (between two events), so f is smooth inside it.
#pragma once

#include <Eigen/Dense>

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
};

}  // namespace vibro
