// SIGINT and SIGTERM stop the server cleanly. A signal handler may do almost nothing safely, so
// it only writes a byte to a pipe; a thread waiting on the pipe calls `stop` outside the handler.
#pragma once

#include <functional>
#include <thread>

namespace vibro::server {

class StopOnSignals {
 public:
  // Installs the handlers; at most one instance at a time.
  explicit StopOnSignals(std::function<void()> stop);
  // Restores the previous handlers and ends the waiting thread.
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  int pipe_[2] = {-1, -1};
  std::thread waiter_;
};

}  // namespace vibro::server
