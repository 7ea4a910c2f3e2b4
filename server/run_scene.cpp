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

std::optional<ApiError> check_sweep(const Scene& scene, const Limits& limits) {
  const SweepSpec& spec = *scene.sweep;
  const double periods = static_cast<double>(sweep_runs(spec)) * (spec.transient + spec.record);
  if (periods > limits.sweep_periods)
    return ApiError{400, "sweep.count",
                    "the sweep asks for " + std::to_string(static_cast<long>(periods)) +
                        " periods (runs × (transient + record)), over the server's limit of " +
                        std::to_string(static_cast<long>(limits.sweep_periods))};
  // The longest run: the period is longest where the swept values make it so, at a corner.
  const SweepAxis one{"", 0.0, 0.0, 1};
  const SweepAxis& a2 = spec.axis2 ? *spec.axis2 : one;
  for (double v : {spec.axis.from, spec.axis.to})
    for (double v2 : {a2.from, a2.to}) {
      Model m = scene.model;
      set_parameter(m, spec.axis.parameter, v);
      if (spec.axis2) set_parameter(m, spec.axis2->parameter, v2);
      const double span = (spec.transient + spec.record) * sweep_period(m);
      if (span > limits.t_end)
        return ApiError{400, "sweep.record",
                        "a run would last " + std::to_string(span) +
                            " s (transient + record "
                            "periods), over the server's limit of " +
                            std::to_string(limits.t_end) + " s"};
    }
  return std::nullopt;
}

std::optional<ApiError> check_orbit(const Scene& scene, const Limits& limits) {
  const OrbitRequest& request = *scene.periodic_orbit;
  const OrbitSpec& spec = request.orbit;
  const double T = forcing_period(scene.model);
  const auto over = [&](const char* field, const std::string& what, double s) {
    return ApiError{400, std::string("periodic_orbit.") + field,
                    what + " would last " + std::to_string(s) +
                        " s of simulated time, over the server's limit of " +
                        std::to_string(limits.t_end) + " s"};
  };
  if (spec.guess.empty() && spec.transient * T > limits.t_end)
    return over("transient", "the run to the starting guess (transient periods)",
                spec.transient * T);
  // Each Newton iteration maps the state over `periods` periods at least once.
  const double search = (spec.max_iterations + 1.0) * spec.periods * T;
  if (search > limits.t_end)
    return over("max_iterations", "the search ((max_iterations + 1) × periods forcing periods)",
                search);
  if (!request.continuation) return std::nullopt;
  // A branch point costs a few corrector iterations, each one map: about this many at most.
  constexpr double kMapsPerPoint = 16.0;
  const double periods = kMapsPerPoint * request.continuation->max_points * spec.periods;
  if (periods > limits.sweep_periods)
    return ApiError{400, "periodic_orbit.continuation.max_points",
                    "the branch may take some " + std::to_string(static_cast<long>(periods)) +
                        " forcing periods (16 maps × max_points × periods), over the server's "
                        "limit of " +
                        std::to_string(static_cast<long>(limits.sweep_periods))};
  Model end = scene.model;
  set_parameter(end, request.continuation->parameter, request.continuation->to);
  const double last = spec.periods * forcing_period(end);
  if (last > limits.t_end)
    return over("continuation.to", "a map at the branch's end (periods forcing periods)", last);
  return std::nullopt;
}

RenderResult draw_orbit_return(const Scene& scene, const PeriodicOrbit& orbit, ImageFormat format) {
  const auto once = orbit_return(scene.model, scene.sim, orbit);
  if (const auto* e = std::get_if<FieldError>(&once)) return {{}, {}, *e, {}};
  const OrbitReturn& r = std::get<OrbitReturn>(once);
  const RunPlan plan = plan_run(scene.figure, r.options, r.model.size());
  return render_figure(scene.figure, r.model, simulate(r.model, plan.options), format);
}

JobResult orbit_image(const Scene& scene, const OrbitResult& result, ImageFormat format) {
  const auto& continuation = scene.periodic_orbit->continuation;
  const OrbitFigure figure{&result.branch, continuation ? &*continuation : nullptr};
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

JobResult work_precision_scene(const Scene& scene, std::optional<ImageFormat> image,
                               const Limits& limits) {
  WorkPrecisionOptions sweep;
  sweep.repeats = 1;
  // About 42 runs (4 methods × 10 tolerances and 2 references), each given a share of the
  // deadline and the whole measurement the deadline of one simulation.
  SimOptions options = bounded(scene.sim, limits);
  options.deadline_ms = limits.deadline_ms / 16.0;
  sweep.deadline_ms = limits.deadline_ms;
  const WorkPrecisionReport report = work_precision(scene.model, options, sweep);
  if (!image) return Produced{work_precision_to_json(report).dump(), "application/json", {}};
  FigureSpec figure = scene.figure;  // its size, and its print size if it has one
  figure.plots = {WorkPrecisionPlot{}};
  RenderResult drawn = render_figure(figure, scene.model, RunResult{}, *image, {&report});
  if (!drawn.ok()) return ApiError::from(*drawn.error);
  return Produced{std::string(drawn.bytes.begin(), drawn.bytes.end()), drawn.content_type, {}};
}

}  // namespace vibro::server
