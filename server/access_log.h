// One line per request on stderr: method, target, status, body bytes and milliseconds, e.g.
//   vibro: GET /api/render?preset=paper&format=png 200 114968 B 1.92 ms
#pragma once

#include "server/http.h"

namespace vibro::server {

class AccessLog {
 public:
  explicit AccessLog(bool enabled) : enabled_(enabled) {}

  // Marks the start of a request. Called on the connection thread that will also write the
  // response, so the time is kept per thread; requests the HTTP layer refuses before routing
  // have no start and log "-" for their time.
  void start() const;
  void write(const httplib::Request& req, const httplib::Response& res) const;

 private:
  bool enabled_;
};

}  // namespace vibro::server
