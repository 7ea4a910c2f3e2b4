// A scene's "periodic_orbit" request (API.md, "Periodic motions and their stability"): the orbit
// to seek and, optionally, the parameter to follow it in; and the one way of carrying it out that
// `vibro orbit` and POST /api/periodic-orbit share.
#pragma once

#include <atomic>
#include <functional>
#include <optional>

#include "core/analysis/bifurcation_curve.h"
#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"
#include "core/model/model.h"
#include "core/run/sim_options.h"
#include "core/run/validate.h"

namespace vibro {

struct OrbitRequest {
  OrbitSpec orbit;  // a scene without "periodic_orbit" gets these defaults
  std::optional<ContinuationSpec> continuation;  // absent: the orbit alone
  // The continuation's "follow" and "parameter2": a bifurcation of the branch to follow in a
  // second parameter (core/analysis/bifurcation_curve.h); only with a continuation.
  std::optional<FollowSpec> follow;
};

// Why the request cannot run on this model, naming the field ("periodic_orbit.periods",
// "model.pellets" when nothing is forced, "periodic_orbit.continuation.to", ...): the orbit and
// the continuation each checked against `limits`.
std::optional<FieldError> validate_orbit_request(const Model& model, const OrbitRequest& request,
                                                 const Limits& limits = {});

struct OrbitResult {
  PeriodicOrbit orbit;
  // Continued from the orbit when the request asks for it and the orbit converged; otherwise
  // no points, and its message says why when a continuation was asked for.
  OrbitBranch branch;
  // The followed bifurcation's curve when the request asks for one (without points, its message
  // saying why, when there was no branch to take it from).
  std::vector<BifurcationCurve> curves;
};

// Finds the orbit, then follows it when the request asks, and then the bifurcation to follow.
// `progress` (0 to 1, the branch and the curve each half when both are made) and `cancel` are
// the continuation's (core/analysis/orbit_continuation.h). Call validate_orbit_request first.
OrbitResult run_orbit_request(const Model& model, const SimOptions& options,
                              const OrbitRequest& request,
                              const std::function<void(double done)>& progress = {},
                              const std::atomic<bool>* cancel = nullptr);

}  // namespace vibro
