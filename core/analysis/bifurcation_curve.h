// Two-parameter curves (API.md, third round, "Two-parameter curves"): a fold, period doubling or
// grazing of a continued branch, followed in a second parameter. The point of the curve at each
// value of the second parameter solves the augmented system
//   P(x; p1) − x = 0,  G(x; p1) = 0
// for the section state x and the first parameter p1, by Newton's method (the map's Jacobian in
// x from core/analysis/monodromy.h, the rest by finite differences), with the test function G:
//   fold             det(M − I)  (a multiplier at +1)
//   period doubling  det(M + I)  (a multiplier at −1)
//   grazing          the signed clearance of the motion to the limiters: the distance from a
//   limiter
//                    of the turning point nearest one (zero speed there), or minus the slowest
//                    impact's speed times sqrt(R/g) when the motion strikes.
// The second parameter is stepped from the scene's own value to `to` and to `from` (natural-
// parameter continuation, the prediction a secant of the last two points). docs/ORBITS.md.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"
#include "core/model/model.h"
#include "core/run/limits.h"
#include "core/run/sim_options.h"
#include "core/run/validate.h"

namespace vibro {

struct FollowSpec {
  BifurcationKind kind = BifurcationKind::fold;  // fold, period_doubling or grazing
  std::string parameter2;                        // a path of core/model/parameter.h
  double from = 0.0, to = 0.0;                   // its range; the scene's value lies in it
};

struct CurvePoint {
  double value = 0.0;   // the first parameter (the continuation's)
  double value2 = 0.0;  // the second
};

struct BifurcationCurve {
  BifurcationKind kind = BifurcationKind::fold;
  std::vector<CurvePoint> points;  // in increasing order of the walk from `from` to `to`
  bool reached_from = false, reached_to = false;
  std::string message;  // how each end of the curve ended: reached, lost, budget, ...
};

// Why the follow cannot run on this model and continuation, naming the field
// ("periodic_orbit.continuation.follow", "periodic_orbit.continuation.parameter2.parameter", ...).
std::optional<FieldError> validate_follow(const Model& model, const ContinuationSpec& continuation,
                                          const FollowSpec& spec, const Limits& limits = {});

// Follows the first bifurcation of spec.kind on `branch` (continued from an orbit of `periods`
// forcing periods in continuation.parameter) in spec.parameter2, at most continuation.max_points
// points. options.deadline_ms bounds the whole walk; `progress` is told the share done (0 to 1);
// `cancel`, once set, stops it after the point in hand.
BifurcationCurve follow_bifurcation(const Model& model, const SimOptions& options, int periods,
                                    const ContinuationSpec& continuation, const OrbitBranch& branch,
                                    const FollowSpec& spec,
                                    const std::function<void(double done)>& progress = {},
                                    const std::atomic<bool>* cancel = nullptr);

}  // namespace vibro
