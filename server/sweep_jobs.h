// Sweeps as jobs (API.md, "Sweeps"): POST /api/sweep queues one and answers at once with its id;
// its progress, result and cancellation are asked for by id. Jobs run on threads of their own,
// so a sweep never takes the workers that answer interactive simulations and renders; a bounded
// number run at once, a bounded queue waits, and finished results are kept for a bounded time
// and number.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/sweep.h"
#include "io/scene.h"

namespace vibro::server {

enum class JobState { queued, running, done, failed, cancelled };
std::string_view job_state_name(JobState state);  // "queued", "running", "done", ...

struct SweepJob {
  std::string id;
  Scene scene;  // with its sweep, its options bounded by the server's limits
  long total = 0;
  std::atomic<long> done{0};
  std::atomic<bool> cancel{false};
  // Guarded by the store's mutex:
  JobState state = JobState::queued;
  std::shared_ptr<const SweepResult> result;  // when done
  std::chrono::steady_clock::time_point finished;
};

struct SweepJobOptions {
  int jobs = 1;            // sweeps running at once
  int threads = 1;         // threads of one sweep
  std::size_t queue = 8;   // sweeps waiting; beyond it, submit refuses
  double keep_s = 600.0;   // a finished sweep's result is kept this long
  std::size_t kept = 32;   // and at most this many finished sweeps
  std::string id_prefix;   // the ids' first characters ("r2-" for replica 2 of a front door)
};

// A snapshot of a job, for the status answer.
struct JobStatus {
  std::string id;
  JobState state = JobState::queued;
  long done = 0;
  long total = 0;
};

class SweepJobs {
 public:
  explicit SweepJobs(const SweepJobOptions& options);
  // Cancels what runs, drops what waits, joins.
  ~SweepJobs();
  SweepJobs(const SweepJobs&) = delete;
  SweepJobs& operator=(const SweepJobs&) = delete;

  // Queues the scene's sweep: its status, or nothing when the queue is full.
  std::optional<JobStatus> submit(Scene scene);
  std::optional<JobStatus> status(const std::string& id);
  // The finished job (its scene and result), or nothing while it runs or when unknown.
  std::shared_ptr<const SweepJob> finished(const std::string& id);
  // Cancels a queued or running job; its status after, or nothing when unknown.
  std::optional<JobStatus> cancel(const std::string& id);

 private:
  void work();
  void forget_old();  // under mutex_
  JobStatus snapshot(const SweepJob& job) const;

  const SweepJobOptions options_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, std::shared_ptr<SweepJob>> jobs_;
  std::deque<std::shared_ptr<SweepJob>> waiting_;
  std::atomic<std::uint64_t> counter_{0};
  std::uint64_t salt_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace vibro::server
