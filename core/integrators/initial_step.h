// Hairer's initial step-size guess HINIT (DOPRI5, DOP853).
#pragma once

#include <algorithm>

#include "core/integrators/error_norm.h"
#include "core/ode.h"

namespace vibro::integrators {

// A first step h with h^order · max(‖f0‖, ‖y''‖) ≈ 0.01 in the tolerance-weighted norm, y'' being
// estimated from one explicit Euler step. Evaluates f once (the caller counts it); y1 and f1 are
// work space of the system's dimension. The result is at most h_max, and positive and finite
// whenever f0 is finite.
double initial_step(const OdeSystem& sys, double t0, const Vec& y0, const Vec& f0, int order,
                    double h_max, const Tolerance& tol, Vec& y1, Vec& f1);

// The first step after start(): the previous segment's proposal (0: none) is a good hint after an
// event, but the new right-hand side may be much faster, so `reach` times HINIT's guess bounds
// it. HINIT alone is far too cautious after an impact: at a stop at φ = 0 the angle's weight is
// its atol, and HINIT's guess comes out a thousand times below the step that succeeds; the
// explicit methods trust the previous step up to 100 times the guess (a step too long is merely
// rejected), which saves 15–40 % of DOP853's right-hand sides on the presets (docs/PERFORMANCE.md).
inline double first_step(double previous, double guess, double reach) {
  return previous > 0.0 ? std::min(previous, reach * guess) : guess;
}

}  // namespace vibro::integrators
