// Lyapunov exponents of the nonsmooth flow (Benettin's method with the exact linearisation of
// core/analysis/monodromy.h): along a run's hybrid path, the transition matrix of each motion
// interval and the saltation matrix of each instant carry an orthonormal frame, re-orthonormalised
// by QR after every interval; the logarithms of the stretches, summed over the time, are the
// exponents.
#pragma once

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro {

// Over the path's segments from the one that reaches past t_from to the path's end.
LyapunovSpectrum lyapunov_spectrum(const Model& model, const std::vector<PathSegment>& path,
                                   double rtol, double t_from = 0.0);

}  // namespace vibro
