// One accepted step as the event search sees it: its span, its state at any time inside, and,
// where the method has them, the polynomials that state is (core/events/crossing_finder.h).
//
// Two kinds of stepper serve it. A dense-output stepper (DOPRI5, DOP853, RADAU5) answers dense()
// and no polynomials: the finder samples the dense output and refines roots on it. A stepper
// whose steps are polynomials (a Taylor method: each component a truncated series in the time
// from the step's start) also answers polynomials(): the finder then takes the roots of a watch
// that is linear in the state (core/events/watch.h, linear_form) on the polynomial itself, and
// samples dense() for the others. Adding such a stepper means overriding polynomials() in its
// class under core/integrators/; the event code does not change.
#pragma once

#include <cstddef>
#include <span>

#include "core/integrators/ode.h"

namespace vibro {

// The state over a step as one polynomial per component in τ = t − t0, the time from the step's
// start: component i is Σ_k coefficient(i, k)·τ^k, k = 0..degree. A view: the stepper owns the
// coefficients, stored component by component (degree + 1 of them each), valid until its next
// step.
struct StepPolynomials {
  double t0 = 0.0;
  int degree = 0;
  std::span<const double> coefficients;  // (degree + 1) per component

  std::span<const double> component(int i) const {
    const std::size_t n = static_cast<std::size_t>(degree) + 1;
    return coefficients.subspan(static_cast<std::size_t>(i) * n, n);
  }
};

class StepView {
 public:
  virtual ~StepView() = default;

  // The last accepted step spans [t_prev(), t()].
  virtual double t_prev() const = 0;
  virtual double t() const = 0;

  // Dense output inside the last accepted step: out = y(t) for t in [t_prev(), t()].
  virtual void dense(double t, Vec& out) const = 0;

  // The step as polynomials, if the method's steps are polynomials; null for a dense output
  // that is only evaluated.
  virtual const StepPolynomials* polynomials() const { return nullptr; }
};

}  // namespace vibro
