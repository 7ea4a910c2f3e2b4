#include "server/sweep_jobs.h"

#include <cstdio>
#include <random>

namespace vibro::server {

std::string_view job_state_name(JobState state) {
  switch (state) {
    case JobState::queued: return "queued";
    case JobState::running: return "running";
    case JobState::done: return "done";
    case JobState::failed: return "failed";
    case JobState::cancelled: return "cancelled";
  }
  return "failed";
}

SweepJobs::SweepJobs(const SweepJobOptions& options) : options_(options) {
  std::random_device random;
  salt_ = (static_cast<std::uint64_t>(random()) << 32) ^ random();
  for (int k = 0; k < std::max(1, options_.jobs); ++k) threads_.emplace_back([this] { work(); });
}

SweepJobs::~SweepJobs() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& [id, job] : jobs_) job->cancel = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

JobStatus SweepJobs::snapshot(const SweepJob& job) const {
  return {job.id, job.state, job.done.load(), job.total};
}

std::optional<JobStatus> SweepJobs::submit(Scene scene) {
  const std::lock_guard lock(mutex_);
  forget_old();
  if (waiting_.size() >= options_.queue) return std::nullopt;
  auto job = std::make_shared<SweepJob>();
  // Ids that a client cannot guess from its own: a per-process salt mixed into a counter.
  char id[24];
  std::snprintf(id, sizeof id, "s%016llx",
                static_cast<unsigned long long>((++counter_ * 0x9E3779B97F4A7C15ULL) ^ salt_));
  job->id = options_.id_prefix + id;
  job->total = sweep_runs(*scene.sweep);
  job->scene = std::move(scene);
  jobs_[job->id] = job;
  waiting_.push_back(job);
  wake_.notify_one();
  return snapshot(*job);
}

std::optional<JobStatus> SweepJobs::status(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  return snapshot(*it->second);
}

std::shared_ptr<const SweepJob> SweepJobs::finished(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second->state != JobState::done) return nullptr;
  return it->second;
}

std::optional<JobStatus> SweepJobs::cancel(const std::string& id) {
  const std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  SweepJob& job = *it->second;
  job.cancel = true;
  if (job.state == JobState::queued) {
    std::erase(waiting_, it->second);
    job.state = JobState::cancelled;
    job.finished = std::chrono::steady_clock::now();
  }
  return snapshot(job);
}

void SweepJobs::forget_old() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<std::shared_ptr<SweepJob>> ended;
  for (const auto& [id, job] : jobs_)
    if (job->state != JobState::queued && job->state != JobState::running) ended.push_back(job);
  std::sort(ended.begin(), ended.end(),
            [](const auto& a, const auto& b) { return a->finished < b->finished; });
  for (std::size_t k = 0; k < ended.size(); ++k) {
    const double age = std::chrono::duration<double>(now - ended[k]->finished).count();
    if (age > options_.keep_s || ended.size() - k > options_.kept) jobs_.erase(ended[k]->id);
  }
}

void SweepJobs::work() {
  for (;;) {
    std::shared_ptr<SweepJob> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !waiting_.empty(); });
      if (stopping_) return;
      job = waiting_.front();
      waiting_.pop_front();
      job->state = JobState::running;
    }
    SweepControl control;
    control.threads = options_.threads;
    control.cancel = &job->cancel;
    control.progress = [&job](long done, long) { job->done = done; };
    JobState ended = JobState::done;
    std::shared_ptr<const SweepResult> result;
    try {
      auto r = std::make_shared<SweepResult>(
          run_sweep(job->scene.model, job->scene.sim, *job->scene.sweep, control));
      ended = r->cancelled ? JobState::cancelled : JobState::done;
      result = std::move(r);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "vibro: sweep %s failed: %s\n", job->id.c_str(), e.what());
      ended = JobState::failed;
    }
    const std::lock_guard lock(mutex_);
    job->result = std::move(result);
    job->state = ended;
    job->finished = std::chrono::steady_clock::now();
  }
}

}  // namespace vibro::server
