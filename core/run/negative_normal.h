// The paper law's normal force per mass of a sliding pellet, N = g cos φ + R φ̇², may fall below
// zero and rise back inside one step, where it is positive at both ends: at a slow passage over
// the circle's top. A long step (Taylor's) holds such a stretch whole; the recorder's check at the
// step's ends alone (core/run/recorder.h) would not see it.
#pragma once

#include <optional>

#include "core/integrators/step_view.h"
#include "core/model/model.h"

namespace vibro {

// Brackets, in time, of where N falls to zero (into the stretch) and rises back (out of it).
struct NegativeStretch {
  double begin_lo, begin_hi;  // N > 0 at begin_lo, ≤ 0 at begin_hi
  double end_lo, end_hi;      // N ≤ 0 at end_lo, > 0 at end_hi
};

// The stretch of pellet `pellet` inside the step [step.t_prev(), t], given N positive at both
// ends, or none; cos_at_t is cos φ at t. On a polynomial step (StepView::polynomials) it is
// proven absent by a bound of N over the step (the pellet's reach in φ and φ̇ over it), else
// found on N's own series, g·cos φ(τ) + R·φ̇(τ)², whose first root and (from the step's end,
// backward) last root bound it. Other steps are searched where the pellet is near the top at
// either end (`near_top`: in the circle's upper half, cos φ < 0, where alone N can be negative,
// slower than sqrt(2g/R); the caller has the states there). Elsewhere N is taken to stay
// positive: its speed would have to fall below sqrt(g/R) and come back within one step. N is
// read at `samples` points of the dense output and, none negative but the parabola through the
// least and its neighbours dipping toward zero, its least value is searched for between those
// neighbours (a golden-section search, which assumes one minimum there).
std::optional<NegativeStretch> negative_normal_inside(const Model& model, const StepView& step,
                                                      int pellet, double t, double cos_at_t,
                                                      bool near_top, int samples = 4);

}  // namespace vibro
