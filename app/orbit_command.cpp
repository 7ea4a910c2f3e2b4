// `vibro orbit SCENE | - | --preset NAME [-o OUT.json|.png|.svg|.pdf]...`: finds the periodic
// motion the scene's "periodic_orbit" asks for (the defaults without one), follows it in a
// parameter when it asks for a continuation, and writes the result as JSON (API.md, "Periodic
// motions and their stability"), to stdout without -o; or draws it (render/orbit_figure.h): the
// continued branch, over the brute-force diagram when the scene's sweep is over the same parameter
// (run here on every core); the bifurcation curves it follows, over the regime map when the sweep
// spans the same two parameters; or else one return of the motion in the scene's plots. While a
// branch is followed or a sweep runs, a progress bar shows on stderr when that is a terminal. Exits
// 1 when no orbit was found: the JSON then says why.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "app/commands.h"
#include "app/progress_bar.h"
#include "app/scene_options.h"
#include "app/usage.h"
#include "io/orbit_json.h"
#include "io/scene_json.h"
#include "render/orbit_figure.h"
#include "server/run_scene.h"

namespace vibro {
namespace {

// The figure of the result, as the scene's plots and its continuation ask (render/orbit_figure.h),
// with the sweep beneath it when one was run.
OrbitFigure figure_of(const Scene& scene, const OrbitRequest& request, const OrbitResult& result,
                      const SweepResult* sweep) {
  return {&result.branch,
          request.continuation ? &*request.continuation : nullptr,
          scene.sweep ? &*scene.sweep : nullptr,
          sweep,
          &result.curves,
          request.follow ? &*request.follow : nullptr};
}

// The scene's sweep, when the figure draws it beneath the branch or the curves.
std::optional<SweepResult> sweep_beneath(const Scene& scene, const OrbitRequest& request,
                                         const OrbitResult& result, ProgressBar& bar) {
  if (!draws_sweep_beneath(figure_of(scene, request, result, nullptr))) return std::nullopt;
  SweepControl control;
  control.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (isatty(STDERR_FILENO))
    control.progress = [&bar](long done, long total) {
      bar(static_cast<double>(done) / total,
          "sweep: " + std::to_string(done) + " of " + std::to_string(total) + " runs");
    };
  SimOptions options = scene.sim;
  options.check = false;
  return run_sweep(scene.model, options, *scene.sweep, control);
}

// The figure of the result: the branch (over the sweep beneath it), or one return of the motion.
// Empty after printing why it cannot be drawn.
std::optional<std::string> orbit_image(const Scene& scene, const OrbitRequest& request,
                                       const OrbitResult& result,
                                       const std::optional<SweepResult>& sweep,
                                       ImageFormat format) {
  const OrbitFigure figure = figure_of(scene, request, result, sweep ? &*sweep : nullptr);
  return drawn_bytes(draws_branch(figure)
                         ? render_branch_figure(scene.figure, scene.model, figure, format)
                         : server::draw_orbit_return(scene, result.orbit, format));
}

int orbit(const SceneOutput& o) {
  const auto loaded = load_scene(o.scene);
  if (!loaded) return 2;
  const Scene& scene = *loaded;
  if (!outputs_named(o.outs, {".json", ".png", ".svg", ".pdf"},
                     "OUT.json, OUT.png, OUT.svg or OUT.pdf"))
    return 2;
  const OrbitRequest request = scene.periodic_orbit.value_or(OrbitRequest{});
  if (auto e = validate_orbit_request(scene.model, request)) {
    print_error(e->field, e->message);
    return 2;
  }
  ProgressBar bar;
  std::function<void(double)> progress;
  if (request.continuation && isatty(STDERR_FILENO))
    progress = [&bar](double done) {
      bar(done, std::to_string(std::lround(100.0 * done)) + "% of the way");
    };
  const OrbitResult result = run_orbit_request(scene.model, scene.sim, request, progress);
  if (progress) bar(1.0, "finished");
  const bool draws = std::any_of(o.outs.begin(), o.outs.end(), [](const std::string& out) {
    return image_format_of_file(out).has_value();
  });
  // Run once for every image that draws it.
  const std::optional<SweepResult> sweep =
      draws ? sweep_beneath(scene, request, result, bar) : std::nullopt;
  // With its scene, so that `vibro plot` redraws it from this output alone.
  nlohmann::json saved = orbit_result_json(result);
  saved["scene"] = scene_to_json(scene);
  const std::string json = saved.dump(2) + "\n";
  if (o.outs.empty()) std::cout << json;  // checked once the command ends (app/main.cpp)
  for (const std::string& out : o.outs) {
    const auto image = image_format_of_file(out);
    const auto bytes = image ? orbit_image(scene, request, result, sweep, *image) : json;
    if (!bytes) return 1;
    if (!write_output(out, *bytes)) return 1;
  }
  return result.orbit.converged ? 0 : 1;
}

}  // namespace

Command add_orbit_command(CLI::App& vibro) {
  auto o = std::make_shared<SceneOutput>();
  CLI::App* command = add_scene_command(
      vibro, "orbit",
      "Find the scene's periodic_orbit (or a period-1 motion after 100 periods), its stability, "
      "and the branch it follows",
      "write OUT.json instead of JSON on stdout, or draw OUT.png, OUT.svg or OUT.pdf", *o);
  return {command, [o] { return orbit(*o); }};
}

}  // namespace vibro
