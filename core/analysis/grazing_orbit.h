// The impacting periodic motion next to a grazing (docs/ORBITS.md, "Through a grazing"). On the
// stroboscopic section the map has a square root there: the time of an impact of low speed
// depends on the state like the square root of how far the free motion would overshoot the
// limiter, so Newton's method on the map converges only very close to such a motion. Taken at the
// impact instead, with its time an unknown and the pellet's angle at it on the limiter, the
// return is smooth through the grazing (the impact's speed passes through zero linearly in the
// parameter), and the impacting motion just past a grazing is found from the grazing motion in a
// few Newton steps.
#pragma once

#include <optional>
#include <vector>

#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/run/sim_options.h"

namespace vibro {

// A limiter impact that appears or vanishes at a grazing.
struct GrazingImpact {
  int pellet = -1, limiter = -1;
  double side = 0.0;  // +1: the pellet strikes it moving up (the limiter above it)
};

// The model without limiter l: the motion the pellets would make if it were not there.
Model without_limiter(Model m, int l);

struct ImpactingOrbit {
  Vec x;               // the state on the section (the model's t = 0)
  double time = 0.0;   // of the impact, s after the section
  double speed = 0.0;  // the pellet's speed just before it, rad/s, signed along phi
  Vec before;          // the state just before it
};

// The periodic motion over `periods` forcing periods of `model` (seen from its section, its
// limiters fixed) that strikes `impact`'s limiter once per return on top of what the free motion
// does, sought from `before`, a state `time` s after the section just before the impact (the
// grazing motion's turn at the limiter). Newton's method on the unknowns (the state before the
// impact, the pellet's angle replaced by the impact's time) and the return to it, the limiter's
// impact applied as a lone pellet's (its speed reversed times k: MODEL.md) and the rest of the
// motion run without the limiter. None where it does not converge to `tol` (rad, speeds times
// sqrt(R/g)) or the speed found is not toward the limiter.
std::optional<ImpactingOrbit> impacting_orbit(const Model& model, const SimOptions& options,
                                              int periods, const GrazingImpact& impact, double time,
                                              const Vec& before, double tol);

}  // namespace vibro
