// A fixed set of threads running simulations and renders from a bounded queue. cpp-httplib's
// own queue grows without bound; this one refuses work when full, so an overloaded server
// answers 503 at once instead of piling up requests that would time out anyway.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace vibro::server {

class WorkerPool {
 public:
  // `threads` ≥ 1 run jobs; at most `capacity` more wait for one.
  WorkerPool(int threads, std::size_t capacity);
  // Runs the jobs already queued, then joins.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Queues the job, or returns false (and drops it) when the queue is full. A job must not
  // throw; it reports failure through its own result channel.
  bool try_post(std::function<void()> job);

 private:
  void work();

  const std::size_t capacity_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::size_t idle_ = 0;  // workers waiting for a job: a job handed to one does not wait
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace vibro::server
