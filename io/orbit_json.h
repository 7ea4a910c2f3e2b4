// Periodic orbits as JSON (API.md, "Periodic motions and their stability"): the scene's
// "periodic_orbit" object, read strictly and written back, and an orbit's result with the branch
// continued from it.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "io/orbit_request.h"

namespace vibro {

// Reads a scene's "periodic_orbit" object, a guess of at most `max_pellets` states and an armed
// set of at most `max_limiters`; throws
// FieldException (io/json_fields.h) naming the field. What depends on the model (the guess's
// count, the parameter's name) is validate_orbit_request's.
OrbitRequest read_orbit_request(const nlohmann::json& json, std::size_t max_pellets,
                                std::size_t max_limiters);
nlohmann::json orbit_request_to_json(const OrbitRequest& request);

// {"orbit": {...}, "branch": [...], "bifurcations": [...], "reached", "message"}, and "curves"
// when the request follows a bifurcation; the branch and bifurcations are empty arrays when
// nothing was continued. Non-finite numbers are null.
nlohmann::json orbit_result_json(const OrbitResult& result);

}  // namespace vibro
