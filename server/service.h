// The HTTP service of `vibro serve`, set up from one ServerConfig: routes, limits, timeouts,
// the worker pool, the cache, error and exception handlers and the access log.
#pragma once

#include <memory>
#include <string>

#include "server/config.h"

namespace vibro::server {

class Service {
 public:
  explicit Service(const ServerConfig& config);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  // Binds config.host:config.port, which no other server may share; returns the port (the one
  // picked for port 0), or -1 with the reason in `why` ("address in use").
  int bind(std::string* why = nullptr);
  // Serves on the bound port until stop(); then finishes the requests under way.
  bool serve();
  // Safe from any thread (not from a signal handler).
  void stop();

  // Renders the paper preset into the cache; false (with the error) if it cannot.
  bool warm_up(std::string& error);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vibro::server
