// Hairer's initial step-size guess HINIT (DOPRI5, DOP853).
#pragma once

#include <algorithm>

#include "core/integrators/error_norm.h"
#include "core/integrators/ode.h"

namespace vibro::integrators {

// A first step h with h^order · max(‖f0‖, ‖y''‖) ≈ 0.01 in the tolerance-weighted norm, y'' being
// estimated from one explicit Euler step. Evaluates f once (the caller counts it); y1 and f1 are
// work space of the system's dimension. The result is at most h_max, and positive and finite
// whenever f0 is finite.
double initial_step(const OdeSystem& sys, double t0, const Vec& y0, const Vec& f0, int order,
                    double h_max, const Tolerance& tol, Vec& y1, Vec& f1);

// The first step after start(): the previous segment's proposal (0: none) is a good hint after an
// event, but the new right-hand side may be much faster, so HINIT's guess bounds it. After an
// impact at a stop HINIT guesses far too short (the angle's weight there is its atol); trusting
// the proposal up to 10 or 100 times the guess saves 8–15 % of DOP853's right-hand sides, but
// the true event-time error grows: runs above what their tolerance asks rose from 6,017 to 7,643
// of 115,000 (tests/differential/trust_scan, seeds 1–8), so the guess stays the bound. A reversal,
// where the motion goes on smoothly, does not come here (Stepper::continue_smoothly).
inline double first_step(double previous, double guess) {
  return previous > 0.0 ? std::min(previous, guess) : guess;
}

}  // namespace vibro::integrators
