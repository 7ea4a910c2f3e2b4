// The closed-form first integral of the unforced paper-law equation on an interval of constant
// sliding direction s (MODEL.md), with a = g/(R cos alpha0) and mu = tan alpha0:
//   dphi² = 2a/(1+4mu²)·[cos(phi + s·alpha0) − 2·s·mu·sin(phi + s·alpha0)] + C·exp(−2·s·mu·phi)
// It is the exact reference for the integrators, and the overlay curve of a phase portrait.
#pragma once

#include "core/model/model.h"

namespace vibro {

class FirstIntegral {
 public:
  // The curve of direction s (+1 or −1) through the state (phi, dphi).
  FirstIntegral(const Model& model, int s, double phi, double dphi);

  // dphi² on the curve at angle phi; negative where the curve does not reach.
  double dphi_squared(double phi) const;
  // Residual of a state against the curve, relative to the curve's speed scale:
  // (dphi² − dphi_squared(phi)) / (dphi0² + 2a).
  double residual(double phi, double dphi) const;
  int direction() const { return s_; }

 private:
  double particular(double phi) const;  // the bracketed term times 2a/(1+4mu²)

  double a_, mu_, alpha0_;
  int s_;
  double C_;
  double scale_;
};

}  // namespace vibro
