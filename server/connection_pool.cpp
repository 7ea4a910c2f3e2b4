#include "server/connection_pool.h"

#include <sys/ioctl.h>
#include <sys/socket.h>

namespace vibro::server {
namespace {

// The slot of the connection thread running this code; none on other threads.
thread_local std::size_t this_slot = static_cast<std::size_t>(-1);

}  // namespace

ConnectionPool::ConnectionPool(int threads)
    : slots_(static_cast<std::size_t>(threads)), free_(slots_.size()) {
  for (std::size_t k = 0; k < slots_.size(); ++k) threads_.emplace_back([this, k] { work(k); });
  watcher_ = std::thread([this] { watch(); });
}

ConnectionPool::~ConnectionPool() {
  if (watcher_.joinable()) shutdown();
}

void ConnectionPool::enqueue(std::function<void()> connection) {
  std::lock_guard lock(mutex_);
  waiting_.push_back(std::move(connection));
  if (waiting_.size() > free_) {
    close_idle();
    crowd_.notify_one();
  }
  wake_.notify_one();
}

void ConnectionPool::shutdown() {
  {
    std::lock_guard lock(mutex_);
    shutdown_ = true;
  }
  wake_.notify_all();
  crowd_.notify_all();
  for (std::thread& t : threads_) t.join();
  watcher_.join();
}

bool ConnectionPool::crowded() const {
  std::lock_guard lock(mutex_);
  return waiting_.size() > free_;
}

void ConnectionPool::idle(const Connection& connection, bool closing) {
  if (this_slot >= slots_.size()) return;
  const int fd = socket_of(connection);
  if (closing) {
    if (fd >= 0) ::shutdown(fd, SHUT_RD);
    return;
  }
  std::lock_guard lock(mutex_);
  slots_[this_slot] = {connection, fd, Clock::now()};
}

void ConnectionPool::busy() {
  if (this_slot >= slots_.size()) return;
  std::lock_guard lock(mutex_);
  slots_[this_slot].fd = -1;
}

void ConnectionPool::close_idle() {
  const Clock::time_point before = Clock::now() - kIdleGrace;
  for (Slot& s : slots_) {
    if (s.fd < 0 || s.idle_since > before) continue;
    // The socket may have been closed and its number reused since it went idle: it is shut
    // only while it is still the same connection.
    if (!is_connection(s.fd, s.connection)) {
      s.fd = -1;
      continue;
    }
    // A request already waiting in it makes it no longer idle: shut now, the client (a front
    // door reusing the connection) would see it closed with its request unanswered.
    int pending = 0;
    if (::ioctl(s.fd, FIONREAD, &pending) == 0 && pending > 0) continue;
    ::shutdown(s.fd, SHUT_RD);
    s.fd = -1;
  }
}

void ConnectionPool::watch() {
  std::unique_lock lock(mutex_);
  while (!shutdown_) {
    if (waiting_.size() > free_) {
      crowd_.wait_for(lock, kIdleGrace / 4);
      close_idle();
    } else {
      crowd_.wait(lock);
    }
  }
}

void ConnectionPool::work(std::size_t slot) {
  this_slot = slot;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return shutdown_ || !waiting_.empty(); });
    if (waiting_.empty()) return;  // shut down, nothing left
    std::function<void()> connection = std::move(waiting_.front());
    waiting_.pop_front();
    --free_;
    lock.unlock();
    connection();
    lock.lock();
    slots_[slot].fd = -1;
    ++free_;
  }
}

}  // namespace vibro::server
