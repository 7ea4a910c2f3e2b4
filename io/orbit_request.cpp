#include "io/orbit_request.h"

#include <string>

#include "core/model/parameter.h"

namespace vibro {

namespace {

// A branch point costs a few corrector iterations, each one map: about this many at most.
constexpr double kMapsPerPoint = 16.0;

// The branch's simulated time: its maps over every point held to limits.sweep_periods, and one
// map at its end (the model at `to`) to limits.t_end, as a scene's run is.
std::optional<FieldError> check_branch_time(const Model& model, const OrbitRequest& request,
                                            const Limits& limits) {
  const std::string field = "periodic_orbit.continuation.";
  const ContinuationSpec& spec = *request.continuation;
  const int periods = request.orbit.periods;
  // A curve's point costs some Newton iterations, each 3 + 2N maps (the test function's
  // derivatives by differences): about twice a branch point's.
  const double per_point = request.follow ? 3.0 * kMapsPerPoint : kMapsPerPoint;
  const double total = per_point * spec.max_points * periods;
  if (total > limits.sweep_periods)
    return FieldError{field + "max_points",
                      "the branch may take some " + std::to_string(static_cast<long>(total)) +
                          " forcing periods (" + std::to_string(static_cast<int>(per_point)) +
                          " maps × max_points × periods), over the limit of " +
                          std::to_string(static_cast<long>(limits.sweep_periods))};
  Model end = model;
  set_parameter(end, spec.parameter, spec.to);
  const double last = periods * forcing_period(end);
  if (last > limits.t_end)
    return FieldError{field + "to",
                      "a map at the branch's end (periods forcing periods) would last " +
                          shortest_text(last) + " s of simulated time, over the limit of " +
                          shortest_text(limits.t_end) + " s"};
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_orbit_request(const Model& model, const OrbitRequest& request,
                                                 const Limits& limits) {
  if (auto e = validate_orbit(model, request.orbit, limits)) return e;
  if (!request.continuation) return std::nullopt;
  if (auto e = validate_continuation(model, *request.continuation, limits)) return e;
  if (request.follow)
    if (auto e = validate_follow(model, *request.continuation, *request.follow, limits)) return e;
  return check_branch_time(model, request, limits);
}

OrbitResult run_orbit_request(const Model& model, const SimOptions& options,
                              const OrbitRequest& request,
                              const std::function<void(double done)>& progress,
                              const std::atomic<bool>* cancel) {
  OrbitResult result;
  result.orbit = find_periodic_orbit(model, options, request.orbit);
  if (!request.continuation) return result;
  // A branch starts from an orbit; without one there is nothing to follow.
  if (!result.orbit.converged) {
    result.branch.message =
        "no branch: the orbit to start from was not found (" + result.orbit.message + ")";
    if (request.follow)
      result.curves.push_back({request.follow->kind, {}, false, false, result.branch.message});
    return result;
  }
  const double share = request.follow ? 0.5 : 1.0;
  const auto part = [&](double offset) {
    return std::function<void(double)>([&progress, offset, share](double done) {
      if (progress) progress(offset + share * done);
    });
  };
  result.branch =
      continue_orbit(model, options, result.orbit, *request.continuation, part(0.0), cancel);
  if (request.follow)
    result.curves.push_back(follow_bifurcation(model, options, request.orbit.periods,
                                               *request.continuation, result.branch,
                                               *request.follow, part(0.5), cancel));
  return result;
}

}  // namespace vibro
