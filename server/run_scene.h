// The work behind /api/simulate, /api/render and /api/periodic-orbit, run on a worker: the
// scene's options bounded by the server's limits, the simulation, the figure, and either the
// answer or an error that says which limit stopped the run.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/analysis/work_precision.h"
#include "io/orbit_request.h"
#include "io/run_csv.h"
#include "io/scene.h"
#include "render/figure.h"
#include "server/api_error.h"
#include "server/config.h"

namespace vibro::server {

struct Produced {
  std::string body;
  std::string content_type;
  std::vector<std::pair<std::string, std::string>> headers;  // sent (and cached) with the body
};

using JobResult = std::variant<Produced, ApiError>;

// What can be known before any work: the image's size, the figure against the model, and no
// work-precision sweep (the command line draws those).
std::optional<ApiError> check_figure(const Scene& scene, ImageFormat format, const Limits& limits);

// The run as API.md's JSON, with the sampled branches if the scene asks for trajectories; or
// (`table`) its events or its sampled trajectory as CSV.
JobResult simulate_scene(const Scene& scene, const Limits& limits,
                         std::optional<RunTable> table = std::nullopt);

// The scene's periodic orbit as API.md's JSON, without continuation (that is a job's); or, when
// `image` names a format, one return of the motion drawn in the scene's plots.
JobResult orbit_scene(const Scene& scene, std::optional<ImageFormat> image = std::nullopt);

// One return of a found periodic motion (core/analysis orbit_return), run within the scene's
// options and drawn in the scene's plots; an orbit not found is an error naming
// "periodic_orbit". Simulates and draws: the server calls it on a worker, `vibro orbit` too.
RenderResult draw_orbit_return(const Scene& scene, const PeriodicOrbit& orbit, ImageFormat format);

// An orbit's result drawn: its continued branch (render/orbit_figure.h) or its curves, over the
// scene's `sweep` when given and the figure draws it, or else one return of the motion, run here,
// in the scene's plots. Simulates and draws: call it on a worker.
JobResult orbit_image(const Scene& scene, const OrbitResult& result, ImageFormat format,
                      const SweepResult* sweep = nullptr);

// The scene's run options within the server's limits (events, steps, deadline per run).
SimOptions bounded_options(const SimOptions& options, const Limits& limits);

// The scene's plots as one image, computing only what they draw.
JobResult render_scene(const Scene& scene, ImageFormat format, const Limits& limits);

// How the server measures work-precision: each point the median of three runs (one run's time
// zig-zags with the machine's load), the whole within the deadline of one simulation.
WorkPrecisionOptions server_work_precision_options(const Limits& limits);

// The work-precision sweep of the scene (runs per method and tolerance as above, each within a
// share of the deadline): its table as JSON, or its diagram when `image` names a format.
JobResult work_precision_scene(const Scene& scene, std::optional<ImageFormat> image,
                               const Limits& limits);

}  // namespace vibro::server
