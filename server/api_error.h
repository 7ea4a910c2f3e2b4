// The one shape of every error answer (API.md): a 4xx or 5xx status with the JSON body
// {"error": "...", "field": "..."}, and extra members where they help (the partial stats of a
// run that hit a limit).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/run/validate.h"
#include "server/http.h"

namespace vibro::server {

struct ApiError {
  int status = 400;
  std::string field;    // as the scene or the query spells it: "model.R", "width", "preset"
  std::string message;  // what was expected
  nlohmann::json extra = nlohmann::json::object();  // merged into the body

  static ApiError from(const FieldError& e, int status = 400) {
    return {status, e.field, e.message, nlohmann::json::object()};
  }
};

// Writes the error as the response: status, JSON body, no caching. `close` also ends the
// connection, for refusals sent before the request body was read.
void send_error(httplib::Response& res, const ApiError& error, bool close = false);

}  // namespace vibro::server
