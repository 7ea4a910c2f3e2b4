// One line per request on stderr: method, target, status, body bytes and milliseconds, e.g.
//   vibro: GET /api/render?preset=paper&format=png 200 114968 B 1.92 ms
#pragma once

#include <cstddef>

#include "server/http.h"

namespace vibro::server {

class AccessLog {
 public:
  explicit AccessLog(bool enabled) : enabled_(enabled) {}

  // Marks the start of a request. Called on the connection thread that will also write the
  // response, so the time is kept per thread; requests the HTTP layer refuses before routing
  // have no start and log "-" for their time.
  void start() const;
  // Counts bytes of a body written by a content provider (a streamed result): res.body is empty
  // then, and the line reports these instead. Called on the connection thread, while writing.
  static void streamed(std::size_t bytes);
  void write(const httplib::Request& req, const httplib::Response& res) const;

 private:
  bool enabled_;
};

}  // namespace vibro::server
