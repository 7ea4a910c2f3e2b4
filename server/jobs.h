// Long work as jobs: a sweep (API.md, "Sweeps", POST /api/sweep) or a periodic orbit followed in
// a parameter ("Periodic motions and their stability", POST /api/periodic-orbit with a
// continuation). Queuing one answers at once with its id; its progress, result and cancellation
// are asked for by id. Jobs run on threads of their own, so they never take the workers that
// answer interactive simulations and renders; a bounded number run at once, a bounded queue
// waits, and finished results are kept for a bounded time and number.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/analysis/sweep.h"
#include "io/orbit_request.h"
#include "io/scene.h"

namespace vibro::server {

enum class JobState { queued, running, done, failed, cancelled };
std::string_view job_state_name(JobState state);  // "queued", "running", "done", ...

// What a job runs: the scene's sweep, or its periodic orbit and the branch continued from it.
enum class JobKind { sweep, orbit };

struct Job {
  std::string id;
  JobKind kind = JobKind::sweep;
  Scene scene;  // with what the job runs, its options bounded by the server's limits
  // An orbit's: the options of the scene's sweep when it may be drawn beneath the branch or its
  // curves (render/orbit_figure.h, sweep_may_lie_beneath); the job then runs that sweep too.
  std::optional<SimOptions> beneath;
  // Progress: a sweep counts its runs; an orbit its way along the parameter, in thousandths,
  // then the runs of the sweep beneath it.
  long total = 0;
  std::atomic<long> done{0};
  std::atomic<bool> cancel{false};
  // Written by the job's thread before its state ends, read only once it has (finished()):
  std::shared_ptr<const SweepResult> sweep;  // a sweep's, or the sweep beneath an orbit's figure
  std::shared_ptr<const OrbitResult> orbit;  // an orbit's
  long points = 0;                           // the section points the sweep holds
  std::optional<FieldError> error;           // why it failed, naming the field to change
  // Guarded by the store's mutex:
  JobState state = JobState::queued;
  std::chrono::steady_clock::time_point finished;
};

struct JobOptions {
  int jobs = 1;           // jobs running at once
  int threads = 1;        // threads of one sweep
  std::size_t queue = 8;  // jobs waiting; beyond it, submit refuses
  double keep_s = 600.0;  // a finished job's result is kept this long
  std::size_t kept = 32;  // and at most this many finished jobs
  std::string id_prefix;  // the ids' first characters ("r2-" for replica 2 of a front door)
  // A sweep's bounds (SweepControl): the points it may keep and its wall clock, ms; past either
  // it fails, naming the field, and keeps nothing. A continuation has the same wall clock.
  long max_points = 0;
  double budget_ms = std::numeric_limits<double>::infinity();
  // The points finished sweeps hold in all, 0: no bound; past it the oldest are forgotten.
  long kept_points = 0;
};

// A snapshot of a job, for the status answer.
struct JobStatus {
  std::string id;
  JobState state = JobState::queued;
  long done = 0;
  long total = 0;
  std::optional<FieldError> error;  // a failed job's reason, when it has one
};

class Jobs {
 public:
  explicit Jobs(const JobOptions& options);
  // Cancels what runs, drops what waits, joins.
  ~Jobs();
  Jobs(const Jobs&) = delete;
  Jobs& operator=(const Jobs&) = delete;

  // Queues the scene's sweep, or its periodic_orbit with a continuation (and, given `beneath`,
  // the scene's sweep to draw beneath it, run with those options): its status, or nothing when
  // the queue is full.
  std::optional<JobStatus> submit(JobKind kind, Scene scene,
                                  std::optional<SimOptions> beneath = std::nullopt);
  std::optional<JobStatus> status(const std::string& id);
  // The finished job (its scene and result), or nothing while it runs or when unknown.
  std::shared_ptr<const Job> finished(const std::string& id);
  // Cancels a queued or running job; its status after, or nothing when unknown.
  std::optional<JobStatus> cancel(const std::string& id);

 private:
  void work();
  // Runs the job to its end and keeps its result; the state it ended in.
  JobState run(Job& job) const;
  JobState run_orbit(Job& job) const;
  // The sweep beneath an orbit's figure, when the figure draws it, within what is left of the
  // job's budget.
  JobState run_sweep_beneath(Job& job, double spent_ms) const;
  // Runs the job's sweep of scene.sweep under `sim` within budget_ms, its progress counted on
  // from done_before, and keeps the result.
  JobState sweep(Job& job, const SimOptions& sim, long done_before, double budget_ms) const;
  // Forgets finished jobs past their time, their number or the points they hold (oldest
  // first). Under mutex_.
  void forget_old();
  JobStatus snapshot(const Job& job) const;

  const JobOptions options_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, std::shared_ptr<Job>> jobs_;
  std::deque<std::shared_ptr<Job>> waiting_;
  std::atomic<std::uint64_t> counter_{0};
  std::uint64_t salt_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace vibro::server
