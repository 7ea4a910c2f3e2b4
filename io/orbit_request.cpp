#include "io/orbit_request.h"

namespace vibro {

std::optional<FieldError> validate_orbit_request(const Model& model, const OrbitRequest& request,
                                                 const Limits& limits) {
  if (auto e = validate_orbit(model, request.orbit, limits)) return e;
  if (request.continuation) return validate_continuation(model, *request.continuation, limits);
  return std::nullopt;
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
    return result;
  }
  result.branch =
      continue_orbit(model, options, result.orbit, *request.continuation, progress, cancel);
  return result;
}

}  // namespace vibro
