// The threads that hold the server's connections (cpp-httplib's task queue), one connection per
// thread for as long as the connection lasts. A new connection must not wait behind idle
// keep-alive ones: while every thread holds a connection and another connection waits for one,
// each response written says "Connection: close" (a busy client reconnects and takes its turn),
// and connections idle for longer than a grace are closed (their read side shut, so their
// threads end them at once). The grace keeps a client that is about to send its next request
// from having it cut off; a client idle longer is treated as every server treats one past its
// keep-alive timeout.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "server/connection.h"
#include "server/http.h"

namespace vibro::server {

class ConnectionPool : public httplib::TaskQueue {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kIdleGrace{100};

  explicit ConnectionPool(int threads);
  ~ConnectionPool() override;

  void enqueue(std::function<void()> connection) override;
  void shutdown() override;

  // Whether a connection waits for a thread.
  bool crowded() const;
  // On a connection thread: its connection has written a response and waits for the next
  // request, which may not come; or, `closing` (the response said "Connection: close"), it is
  // done, and its read side is shut at once so that its thread need not wait for the client.
  void idle(const Connection& connection, bool closing = false);
  // On a connection thread: a request has come on its connection.
  void busy();

 private:
  struct Slot {
    Connection connection;
    int fd = -1;  // the idle connection's socket, or -1
    Clock::time_point idle_since;
  };
  void work(std::size_t slot);
  void watch();       // while crowded, closes connections idle past the grace
  void close_idle();  // with mutex_ held

  mutable std::mutex mutex_;
  std::condition_variable wake_, crowd_;
  std::deque<std::function<void()>> waiting_;
  std::vector<Slot> slots_;
  std::size_t free_ = 0;  // threads holding no connection
  bool shutdown_ = false;
  std::vector<std::thread> threads_;
  std::thread watcher_;
};

}  // namespace vibro::server
