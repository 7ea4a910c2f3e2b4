#include "server/run_scene.h"

#include <algorithm>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/analysis/checked_run.h"
#include "core/analysis/work_precision.h"
#include "core/model/parameter.h"
#include "io/orbit_json.h"
#include "io/result_json.h"
#include "io/work_precision_json.h"
#include "render/orbit_figure.h"
#include "render/run_plan.h"

namespace vibro::server {
namespace {

// The scene's options within the server's limits. Recorded branches are thinned to the sample
// limit (SimOptions::max_samples): a long run is drawn whole, not stopped for its samples.
SimOptions bounded(SimOptions options, const Limits& limits) {
  options.max_events = std::min(options.max_events, limits.events);
  options.max_steps = std::min(options.max_steps, limits.steps);
  options.deadline_ms = std::min(options.deadline_ms, limits.deadline_ms);
  options.max_samples = limits.samples;
  return options;
}

// A run that a limit stopped is refused (422) with its partial stats; a completed run, or one
// the numerics ended (its result says so), is an answer.
std::optional<ApiError> stopped_by_limit(const RunResult& run, const Scene& scene,
                                         const SimOptions& options, const Limits& limits) {
  const Stats& st = run.stats;
  std::ostringstream why;
  switch (st.termination) {
    case Termination::completed:
    case Termination::numerical_failure:
      return std::nullopt;
    case Termination::deadline:
      why << "the run took longer than its deadline of " << limits.deadline_ms << " ms";
      break;
    case Termination::event_limit:
      why << "the run has more than the server's limit of " << options.max_events << " events";
      break;
    case Termination::step_limit:
      why << "the run needs more than the server's limit of " << options.max_steps << " steps";
      break;
    case Termination::cancelled:  // the server cancels jobs between runs, never a run
      why << "the run was cancelled";
      break;
  }
  why << " (stopped at t = " << st.t_reached << " s of t_end = " << options.t_end << " s); ";
  if (st.termination == Termination::event_limit) {
    // Events are the motion's own: no tolerance changes how many there are.
    why << "shorten t_end to at most " << std::setprecision(3) << 0.95 * st.t_reached
        << " s (no tolerance changes how many events the motion has)";
  } else {
    why << "shorten t_end or loosen the tolerances";
  }
  ApiError error{422, "t_end", why.str()};
  error.extra["stats"] = result_to_json(run, scene.model)["stats"];
  return error;
}

// Where the phase and time plots lie, as compact JSON: [{"kind": "phase"|"time", "pellet",
// "left", "top", "width", "height", "x": [lo, hi], "y": [lo, hi]}], image pixels and the axes'
// spans (render/figure.h, PlotAxes); the page reads clicks and places markers from it.
std::string plot_axes_header(const std::vector<PlotAxes>& axes) {
  nlohmann::json list = nlohmann::json::array();
  for (const PlotAxes& a : axes)
    list.push_back({{"kind", a.kind == PlotAxesKind::phase ? "phase" : "time"},
                    {"pellet", a.pellet},
                    {"left", a.left},
                    {"top", a.top},
                    {"width", a.width},
                    {"height", a.height},
                    {"x", {a.x_lo, a.x_hi}},
                    {"y", {a.y_lo, a.y_hi}}});
  return list.dump();
}

}  // namespace

std::optional<ApiError> check_figure(const Scene& scene, ImageFormat format, const Limits& limits) {
  const FigureSpec& f = scene.figure;
  if (auto e = check_figure_size(f, limits)) return ApiError::from(*e);
  for (std::size_t i = 0; i < f.plots.size(); ++i) {
    // A sweep is some 120 timed runs: far over one request's budget, and its timings would make
    // the same scene give different bytes.
    if (std::holds_alternative<WorkPrecisionPlot>(f.plots[i])) {
      return ApiError{400, "plots[" + std::to_string(i) + "].kind",
                      "a work-precision diagram is a sweep of many timed runs: ask POST "
                      "/api/work-precision?format=png for it"};
    }
  }
  if (auto e = validate_figure(f, scene.model, format, limits)) return ApiError::from(*e);
  return std::nullopt;
}

RenderResult draw_orbit_return(const Scene& scene, const PeriodicOrbit& orbit, ImageFormat format) {
  const auto once = orbit_return(scene.model, scene.sim, orbit);
  if (const auto* e = std::get_if<FieldError>(&once)) return {{}, {}, *e, {}};
  const OrbitReturn& r = std::get<OrbitReturn>(once);
  const RunPlan plan = plan_run(scene.figure, r.options, r.model.size());
  return render_figure(scene.figure, r.model, simulate(r.model, plan.options), format);
}

JobResult orbit_image(const Scene& scene, const OrbitResult& result, ImageFormat format,
                      const SweepResult* sweep) {
  const auto& continuation = scene.periodic_orbit->continuation;
  const auto& follow = scene.periodic_orbit->follow;
  const OrbitFigure figure{.branch = &result.branch,
                           .continuation = continuation ? &*continuation : nullptr,
                           .sweep_spec = sweep && scene.sweep ? &*scene.sweep : nullptr,
                           .sweep = sweep,
                           .curves = &result.curves,
                           .follow = follow ? &*follow : nullptr};
  const RenderResult image = draws_branch(figure)
                                 ? render_branch_figure(scene.figure, scene.model, figure, format)
                                 : draw_orbit_return(scene, result.orbit, format);
  if (!image.ok())
    return ApiError::from(*image.error, image.error->field == "periodic_orbit" ? 422 : 500);
  return Produced{std::string(image.bytes.begin(), image.bytes.end()), image.content_type, {}};
}

JobResult orbit_scene(const Scene& scene, std::optional<ImageFormat> image) {
  const OrbitResult result = run_orbit_request(scene.model, scene.sim, *scene.periodic_orbit);
  if (image) return orbit_image(scene, result, *image);
  return Produced{orbit_result_json(result).dump(), "application/json", {}};
}

SimOptions bounded_options(const SimOptions& options, const Limits& limits) {
  return bounded(options, limits);
}

JobResult simulate_scene(const Scene& scene, const Limits& limits, std::optional<RunTable> table) {
  SimOptions options = scene.sim;
  options.record.assign(scene.model.size(),
                        table ? *table == RunTable::trajectory : scene.trajectories);
  const SimOptions b = bounded(std::move(options), limits);
  const RunResult run = simulate(scene.model, b);
  if (auto error = stopped_by_limit(run, scene, b, limits)) return *error;
  if (table) return Produced{run_csv(run, *table), "text/csv", {}};
  return Produced{result_to_json(run, scene.model).dump(), "application/json", {}};
}

JobResult render_scene(const Scene& scene, ImageFormat format, const Limits& limits) {
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const SimOptions b = bounded(plan.options, limits);
  const RunResult run = simulate(scene.model, b);
  if (auto error = stopped_by_limit(run, scene, b, limits)) return *error;
  RenderResult image = render_figure(scene.figure, scene.model, run, format);
  if (!image.ok()) return ApiError::from(*image.error);
  Produced p{std::string(image.bytes.begin(), image.bytes.end()), image.content_type, {}};
  if (!image.plot_axes.empty())
    p.headers.emplace_back("X-Vibro-Plot-Axes", plot_axes_header(image.plot_axes));
  return p;
}

WorkPrecisionOptions server_work_precision_options(const Limits& limits) {
  WorkPrecisionOptions sweep;
  sweep.repeats = 3;
  sweep.deadline_ms = limits.deadline_ms;
  return sweep;
}

JobResult work_precision_scene(const Scene& scene, std::optional<ImageFormat> image,
                               const Limits& limits) {
  // About 42 points (4 methods × 10 tolerances and 2 references), each run given a share of
  // the deadline and the whole measurement the deadline of one simulation.
  SimOptions options = bounded(scene.sim, limits);
  options.deadline_ms = limits.deadline_ms / 16.0;
  const WorkPrecisionReport report =
      work_precision(scene.model, options, server_work_precision_options(limits));
  if (!image) return Produced{work_precision_to_json(report).dump(), "application/json", {}};
  FigureSpec figure = scene.figure;  // its size, and its print size if it has one
  figure.plots = {WorkPrecisionPlot{}};
  RenderResult drawn = render_figure(figure, scene.model, RunResult{}, *image, {&report});
  if (!drawn.ok()) return ApiError::from(*drawn.error);
  return Produced{std::string(drawn.bytes.begin(), drawn.bytes.end()), drawn.content_type, {}};
}

}  // namespace vibro::server
