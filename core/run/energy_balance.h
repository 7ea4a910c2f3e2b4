// The energy balance of a run: E(t) − E(0) = W(t) + K, with W the work of the forces and of
// friction (integrated with the motion, the third component of each pellet's state) and K the
// energy changed at instants: the kinetic energy of impacts, merges and chatter, and what snapping
// moves (pellets within 1e-10 rad put onto one place or onto a limiter's angle, a speed within
// round-off set to zero: the contact model's regularization, booked here because over 10⁴ events
// it added up to 4e-7 of the energy scale). Both sides are exact for the exact solution, so the
// defect measures the integration error.
#pragma once

#include "core/integrators/ode.h"
#include "core/model/model.h"

namespace vibro {

class EnergyBalance {
 public:
  EnergyBalance(const Model& model, const Vec& y0);

  void add_instant(double kinetic_change) { kinetic_change_ += kinetic_change; }
  // The energy a snap moved, from the state before it to the state after.
  void add_snap(const Vec& before, const Vec& after) {
    kinetic_change_ += total_energy(after) - total_energy(before);
  }
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
