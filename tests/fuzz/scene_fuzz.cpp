// libFuzzer target: arbitrary bytes as a scene. Whatever parses is simulated and drawn with
// small limits, and the run's contract (tests/robustness/run_invariants.h) is checked; a scene
// with a periodic_orbit also has its orbit sought (a few Newton steps, no continuation: that is
// a job's, bounded by the server's cost checks). A broken invariant aborts so that libFuzzer
// keeps the input. Built only with VIBRO_BUILD_FUZZ (clang).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/analysis/checked_run.h"
#include "io/orbit_json.h"
#include "io/orbit_request.h"
#include "io/scene_json.h"
#include "render/figure.h"
#include "render/run_plan.h"
#include "tests/robustness/run_invariants.h"

namespace {

using namespace vibro;

void check(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "scene_fuzz: invariant violated: %s\n", what.c_str());
  std::abort();
}

// Small enough that one input costs at most a few hundred milliseconds.
Limits fuzz_limits() {
  Limits limits;
  limits.t_end = 5.0;
  limits.pellets = 4;
  limits.limiters = 4;
  limits.plots = 2;
  limits.width = 256;
  limits.height = 256;
  return limits;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  SceneOrError parsed = scene_from_text(text, fuzz_limits());
  auto* scene = std::get_if<Scene>(&parsed);
  if (!scene) {
    check(!std::get<FieldError>(parsed).field.empty(), "every refusal names a field");
    return 0;
  }
  // 3-D panels load OSMesa and work-precision panels run a sweep of whole simulations: both
  // too slow for fuzzing, so they are drawn as phase portraits of the same pellet.
  for (PlotSpec& p : scene->figure.plots) {
    PhasePlot phase;
    if (const auto* cylinder = std::get_if<CylinderPlot>(&p)) {
      static_cast<TimeWindow&>(phase) = *cylinder;
      phase.pellet = cylinder->pellet;
      phase.title = cylinder->title;
      p = phase;
    } else if (const auto* report = std::get_if<WorkPrecisionPlot>(&p)) {
      static_cast<TimeWindow&>(phase) = *report;
      phase.title = report->title;
      p = phase;
    }
  }
  // Both output formats, chosen by the input's length so each is covered.
  const ImageFormat format = size % 2 ? ImageFormat::svg : ImageFormat::png;
  if (validate_figure(scene->figure, scene->model, format)) return 0;

  RunPlan plan = plan_run(scene->figure, scene->sim, scene->model.size());
  plan.options.max_events = 2000;
  plan.options.max_steps = 20000;
  plan.options.deadline_ms = 200.0;
  const RunResult run = simulate(scene->model, plan.options);
  const std::string violation = robustness::run_violation(run, scene->model, plan.options.t_end);
  check(violation.empty(), violation);

  const RenderResult image = render_figure(scene->figure, scene->model, run, format);
  if (image.ok())
    check(!image.bytes.empty(), "a drawn figure has bytes");
  else
    check(!image.error->field.empty(), "a render error names its field");

  if (!scene->periodic_orbit) return 0;
  OrbitRequest request = *scene->periodic_orbit;
  request.continuation.reset();
  request.orbit.periods = std::min(request.orbit.periods, 2);
  request.orbit.transient = std::min(request.orbit.transient, 5);
  request.orbit.max_iterations = std::min(request.orbit.max_iterations, 3);
  if (const auto e = validate_orbit_request(scene->model, request)) {
    check(!e->field.empty(), "an orbit refusal names a field");
    return 0;
  }
  SimOptions options = plan.options;
  options.t_end = scene->sim.t_end;
  const OrbitResult found = run_orbit_request(scene->model, options, request);
  const PeriodicOrbit& o = found.orbit;
  if (o.converged) {
    check(std::isfinite(o.residual), "a converged orbit's residual is finite");
    for (const auto& mu : o.multipliers)
      check(std::isfinite(std::abs(mu)), "multipliers are finite");
    for (const PhasePoint& p : o.state)
      check(std::isfinite(p.phi) && std::isfinite(p.dphi), "the state is finite");
  } else {
    check(!o.message.empty(), "an orbit not found says why");
  }
  check(!orbit_result_json(found).dump().empty(), "the orbit's answer is JSON");
  return 0;
}
