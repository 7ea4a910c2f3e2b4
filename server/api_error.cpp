#include "server/api_error.h"

namespace vibro::server {

void send_error(httplib::Response& res, const ApiError& error, bool close) {
  nlohmann::json body = {{"error", error.message}, {"field", error.field}};
  if (error.extra.is_object()) body.update(error.extra);
  res.status = error.status;
  res.set_header("Cache-Control", "no-store");
  if (close) res.set_header("Connection", "close");
  // Invalid UTF-8 from a client's own text (a field name, a path) is replaced, never thrown.
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

}  // namespace vibro::server
