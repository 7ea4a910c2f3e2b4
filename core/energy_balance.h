// The energy balance of a run: E(t) − E(0) = W(t) + K, with W the work of the forces and of
// friction (integrated with the motion, the third component of each pellet's state) and K the
// kinetic energy changed at instants (impacts, merges, chatter). Both sides are exact for the
// exact solution, so the defect measures the integration error.
#pragma once

#include "core/model.h"
#include "core/ode.h"

namespace vibro {

class EnergyBalance {
 public:
  EnergyBalance(const Model& model, const Vec& y0);

  void add_instant(double kinetic_change) { kinetic_change_ += kinetic_change; }
  // Checks the balance at the state y (at events and at the end: a cos per pellet is not worth
  // paying at every step).
  void check(const Vec& y);
  // The largest defect so far, relative to the energy scale (initial kinetic energy plus the
  // potential's range, or the work done if larger).
  double max_defect() const { return max_defect_; }

 private:
  double total_energy(const Vec& y) const;

  const Model& model_;
  double energy0_;
  double scale_;
  double kinetic_change_ = 0.0;
  double max_defect_ = 0.0;
};

}  // namespace vibro
