// The handlers of the endpoints in API.md, and the shared path behind the costly ones:
// canonical key → If-None-Match → cache → bounded worker queue → answer.
#pragma once

#include <functional>
#include <string>

#include "io/scene.h"
#include "server/config.h"
#include "server/http.h"
#include "server/jobs.h"
#include "server/response_cache.h"
#include "server/run_scene.h"
#include "server/static_files.h"
#include "server/worker_pool.h"

namespace vibro::server {

class Api {
 public:
  explicit Api(const ServerConfig& config);

  void health(const httplib::Request& req, httplib::Response& res) const;
  void limits(const httplib::Request& req, httplib::Response& res) const;
  void preset_list(const httplib::Request& req, httplib::Response& res) const;
  void preset(const httplib::Request& req, httplib::Response& res) const;  // /api/presets/{name}
  void simulate_post(const httplib::Request& req, httplib::Response& res);
  void simulate_get(const httplib::Request& req, httplib::Response& res);  // ?preset=NAME
  void render_post(const httplib::Request& req, httplib::Response& res);
  void render_get(const httplib::Request& req, httplib::Response& res);  // ?preset=NAME
  // ?format=json|png|svg: the work-precision sweep of the scene; timings differ from run to
  // run, so it is never cached.
  void work_precision_post(const httplib::Request& req, httplib::Response& res);
  void static_file(const httplib::Request& req, httplib::Response& res) const;
  // The scene's periodic orbit (its "periodic_orbit", or the defaults): answered at once, or
  // with a continuation queued as a job like a sweep.
  void orbit_post(const httplib::Request& req, httplib::Response& res);
  // Sweeps as jobs: 202 with the id; /api/jobs/{id} its progress, /api/jobs/{id}/result?format=
  // json|csv|png|svg its points or diagram (an orbit's: json), DELETE cancels.
  void sweep_post(const httplib::Request& req, httplib::Response& res);
  void job_get(const httplib::Request& req, httplib::Response& res);
  void job_delete(const httplib::Request& req, httplib::Response& res);

  // Draws the paper preset into the cache, as GET /api/render?preset=paper asks for it, so the
  // page's first figure is ready. False (with the error) if that fails.
  bool warm_up(std::string& error);

  const StaticFiles& web() const { return web_; }

 private:
  void simulate(const Scene& scene, const httplib::Request& req, httplib::Response& res);
  void render(const Scene& scene, const httplib::Request& req, httplib::Response& res);
  // Queues the job: 202 with its status and Location, or 503 when the queue is full.
  void submit(JobKind kind, Scene scene, httplib::Response& res,
              std::optional<SimOptions> beneath = std::nullopt);
  // The options of the scene's sweep when it may be drawn beneath its continued orbit (run in the
  // orbit's job, each run's deadline its share of the budget); nothing without one; refused, naming
  // the field, past the server's limits (check_sweep_cost).
  std::variant<std::optional<SimOptions>, ApiError> sweep_beneath_options(const Scene& scene) const;
  // A done sweep's points or diagram, as the query asks.
  void sweep_result(const Job& job, const httplib::Request& req, httplib::Response& res);
  // Answers from the cache, or runs `job` on a worker and caches what it produces.
  void answer(const std::string& key, std::function<JobResult()> job, const httplib::Request& req,
              httplib::Response& res);
  // Runs `job` on a worker; empty when the queue is full (the 503 is then sent).
  std::optional<JobResult> run_on_worker(std::function<JobResult()> job, httplib::Response& res);

  const ServerConfig config_;
  const std::string preset_list_;  // the JSON of GET /api/presets, made once
  StaticFiles web_;
  ResponseCache cache_;
  Jobs jobs_;
  WorkerPool workers_;  // last: its destructor runs queued jobs, which use the members above
};

}  // namespace vibro::server
