#include "server/jobs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "render/orbit_figure.h"

namespace vibro::server {

std::string_view job_state_name(JobState state) {
  switch (state) {
    case JobState::queued:
      return "queued";
    case JobState::running:
      return "running";
    case JobState::done:
      return "done";
    case JobState::failed:
      return "failed";
    case JobState::cancelled:
      return "cancelled";
  }
  return "failed";
}

Jobs::Jobs(const JobOptions& options) : options_(options) {
  std::random_device random;
  salt_ = (static_cast<std::uint64_t>(random()) << 32) ^ random();
  for (int k = 0; k < std::max(1, options_.jobs); ++k) threads_.emplace_back([this] { work(); });
}

Jobs::~Jobs() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& [id, job] : jobs_) job->cancel = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

JobStatus Jobs::snapshot(const Job& job) const {
  // The error is the job thread's until the state says it has ended.
  const bool failed = job.state == JobState::failed;
  return {job.id, job.state, job.done.load(), job.total, failed ? job.error : std::nullopt};
}

std::optional<JobStatus> Jobs::submit(JobKind kind, Scene scene,
                                      std::optional<SimOptions> beneath) {
  const std::lock_guard lock(mutex_);
  forget_old();
  if (waiting_.size() >= options_.queue) return std::nullopt;
  auto job = std::make_shared<Job>();
  // Ids that a client cannot guess from its own: a per-process salt mixed into a counter.
  char id[24];
  std::snprintf(id, sizeof id, "%c%016llx", kind == JobKind::sweep ? 's' : 'o',
                static_cast<unsigned long long>((++counter_ * 0x9E3779B97F4A7C15ULL) ^ salt_));
  job->id = options_.id_prefix + id;
  job->kind = kind;
  job->total = kind == JobKind::sweep ? sweep_runs(*scene.sweep) : 1000;
  if (kind == JobKind::orbit && beneath) job->total += sweep_runs(*scene.sweep);
  job->beneath = std::move(beneath);
  job->scene = std::move(scene);
  jobs_[job->id] = job;
  waiting_.push_back(job);
  wake_.notify_one();
  return snapshot(*job);
}

std::optional<JobStatus> Jobs::status(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  return snapshot(*it->second);
}

std::shared_ptr<const Job> Jobs::finished(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second->state != JobState::done) return nullptr;
  return it->second;
}

std::optional<JobStatus> Jobs::cancel(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  const std::shared_ptr<Job> held = it->second;  // forget_old() may drop it from jobs_
  Job& job = *held;
  job.cancel = true;
  if (job.state == JobState::queued) {
    std::erase(waiting_, held);
    job.state = JobState::cancelled;
    job.finished = std::chrono::steady_clock::now();
    forget_old();
  }
  return snapshot(job);
}

void Jobs::forget_old() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<std::shared_ptr<Job>> ended;
  for (const auto& [id, job] : jobs_)
    if (job->state != JobState::queued && job->state != JobState::running) ended.push_back(job);
  std::sort(ended.begin(), ended.end(),
            [](const auto& a, const auto& b) { return a->finished < b->finished; });
  long points = 0;
  for (const auto& job : ended) points += job->points;
  for (std::size_t k = 0; k < ended.size(); ++k) {
    const double age = std::chrono::duration<double>(now - ended[k]->finished).count();
    const bool too_many_points = options_.kept_points > 0 && points > options_.kept_points;
    if (age > options_.keep_s || ended.size() - k > options_.kept || too_many_points) {
      points -= ended[k]->points;
      jobs_.erase(ended[k]->id);
    }
  }
}

JobState Jobs::run_orbit(Job& job) const {
  const Scene& scene = job.scene;
  // A continuation answers to the job's wall-clock budget as a sweep does: past it, the
  // branch stops after the point in hand and the job fails, saying so.
  const auto started = std::chrono::steady_clock::now();
  auto spent_ms = [&started] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
        .count();
  };
  bool over_budget = false;
  auto progress = [&](double done) {
    job.done = std::lround(1000.0 * done);
    if (spent_ms() > options_.budget_ms && !job.cancel) over_budget = job.cancel = true;
  };
  job.orbit = std::make_shared<OrbitResult>(
      run_orbit_request(scene.model, scene.sim, *scene.periodic_orbit, progress, &job.cancel));
  if (over_budget) {
    job.error = FieldError{"periodic_orbit.continuation.max_points",
                           "the continuation took longer than the job's budget of " +
                               std::to_string(std::lround(options_.budget_ms / 1000.0)) +
                               " s: ask fewer points or a shorter range"};
    return JobState::failed;
  }
  if (job.cancel) return JobState::cancelled;
  return run_sweep_beneath(job, spent_ms());
}

JobState Jobs::run_sweep_beneath(Job& job, double spent_ms) const {
  const Scene& scene = job.scene;
  const OrbitRequest& request = *scene.periodic_orbit;
  const OrbitFigure figure{&job.orbit->branch, &*request.continuation,
                           &*scene.sweep,      nullptr,
                           &job.orbit->curves, request.follow ? &*request.follow : nullptr};
  job.done = 1000;
  if (!job.beneath || !draws_sweep_beneath(figure)) {
    job.done = job.total;
    return JobState::done;
  }
  return sweep(job, *job.beneath, 1000, std::max(0.0, options_.budget_ms - spent_ms));
}

JobState Jobs::run(Job& job) const {
  if (job.kind == JobKind::orbit) return run_orbit(job);
  return sweep(job, job.scene.sim, 0, options_.budget_ms);
}

JobState Jobs::sweep(Job& job, const SimOptions& sim, long done_before, double budget_ms) const {
  SweepControl control;
  control.threads = options_.threads;
  control.cancel = &job.cancel;
  control.progress = [&job, done_before](long done, long) { job.done = done_before + done; };
  control.max_points = options_.max_points;
  control.budget_ms = budget_ms;
  auto result =
      std::make_shared<SweepResult>(run_sweep(job.scene.model, sim, *job.scene.sweep, control));
  if (result->cancelled) return JobState::cancelled;
  // A sweep a bound stopped has no whole result: it keeps nothing, and says why.
  if (result->stopped) {
    job.error = result->stopped;
    return JobState::failed;
  }
  for (const SweepRun& r : result->runs) job.points += static_cast<long>(r.points.size());
  job.sweep = std::move(result);
  return JobState::done;
}

void Jobs::work() {
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !waiting_.empty(); });
      if (stopping_) return;
      job = waiting_.front();
      waiting_.pop_front();
      job->state = JobState::running;
    }
    JobState ended = JobState::failed;
    try {
      ended = run(*job);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "vibro: job %s failed: %s\n", job->id.c_str(), e.what());
      job->error = FieldError{"server", "internal error"};
    }
    const std::lock_guard lock(mutex_);
    job->state = ended;
    job->finished = std::chrono::steady_clock::now();
    // Here as well as on submit: the jobs queued behind the last submit end after it, and
    // would otherwise all be kept on top of `kept`; and a finished sweep's points count
    // against the bound at once.
    forget_old();
  }
}

}  // namespace vibro::server
