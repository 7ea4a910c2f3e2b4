// Lyapunov exponents of the nonsmooth flow (Benettin's method with the exact linearisation of
// core/monodromy.h): along a run's hybrid path, the transition matrix of each motion interval and
// the saltation matrix of each instant carry an orthonormal frame, re-orthonormalised by QR after
// every interval; the logarithms of the stretches, summed over the time, are the exponents.
#pragma once

#include <string>
#include <vector>

#include "core/model.h"
#include "core/result.h"

namespace vibro {

struct LyapunovSpectrum {
  // 1/s, largest first, one per phase-space dimension (2 per pellet). −infinity for a direction
  // perturbations die in: a pellet held by friction or resting on a limiter keeps no memory of
  // how it got there.
  std::vector<double> exponents;
  double span = 0.0;        // s: the time they are averaged over
  std::string unsupported;  // non-empty: the path holds what the saltations do not cover
};

// Over the path's segments from the one that reaches past t_from to the path's end.
LyapunovSpectrum lyapunov_spectrum(const Model& model, const std::vector<PathSegment>& path,
                                   double rtol, double t_from = 0.0);

}  // namespace vibro
