// The threads that hold the server's connections (cpp-httplib's task queue), one connection per
// thread for as long as the connection lasts. A new connection must not wait behind idle
// keep-alive ones: while every thread holds a connection and another connection waits for one,
// the idle connections are closed (their read side shut, so their threads end them at once and
// take the waiting ones) and each response written says "Connection: close". A client that
// keeps its connection busy keeps it; one that leaves it idle gives its thread to the next.
#pragma once

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
  explicit ConnectionPool(int threads);
  ~ConnectionPool() override;

  void enqueue(std::function<void()> connection) override;
  void shutdown() override;

  // Whether a connection waits for a thread.
  bool crowded() const;
  // On a connection thread: its connection has written a response and waits for the next
  // request, which may not come; closed at once if a connection waits, or later does.
  void idle(const Connection& connection);
  // On a connection thread: a request has come on its connection.
  void busy();

 private:
  struct Slot {
    Connection connection;
    int fd = -1;  // the idle connection's socket, or -1
  };
  void work(std::size_t slot);
  void close_idle();  // with mutex_ held

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> waiting_;
  std::vector<Slot> slots_;
  std::size_t free_ = 0;  // threads holding no connection
  bool shutdown_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace vibro::server
