// The product's own speed on the paper scene (1200×800): simulate, simulate + PNG, simulate +
// SVG, a 3-D cylinder panel at 1024×1024, and the simulate time of each method.
#include <benchmark/benchmark.h>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "render/figure.h"
#include "render/run_plan.h"

namespace vibro::bench {
namespace {

// Simulates what the scene's figure needs (as `vibro render` does) and draws it if asked.
void run_scene(benchmark::State& state, const Scene& scene, std::optional<ImageFormat> format) {
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  std::size_t bytes = 0;
  long steps = 0;
  for (auto _ : state) {
    RunResult run = simulate(scene.model, plan.options);
    steps = run.stats.steps;
    if (format) {
      RenderResult image = render_figure(scene.figure, scene.model, run, *format);
      if (!image.ok()) {
        state.SkipWithError(image.error->message.c_str());
        return;
      }
      bytes = image.bytes.size();
    }
    benchmark::DoNotOptimize(run);
  }
  state.counters["steps"] = static_cast<double>(steps);
  if (format) state.counters["bytes"] = static_cast<double>(bytes);
}

void BM_PaperSimulate(benchmark::State& state) {
  run_scene(state, preset_scene("paper"), std::nullopt);
}
BENCHMARK(BM_PaperSimulate)->Unit(benchmark::kMillisecond);

void BM_PaperSimulatePng(benchmark::State& state) {
  run_scene(state, preset_scene("paper"), ImageFormat::png);
}
BENCHMARK(BM_PaperSimulatePng)->Unit(benchmark::kMillisecond);

void BM_PaperSimulateSvg(benchmark::State& state) {
  run_scene(state, preset_scene("paper"), ImageFormat::svg);
}
BENCHMARK(BM_PaperSimulateSvg)->Unit(benchmark::kMillisecond);

// The paper run drawn as one 3-D cylinder panel of pellet 1. The first 3-D panel of a process
// creates the OSMesa context (and dlopens libOSMesa): drawn once before timing.
void BM_Cylinder1024Png(benchmark::State& state) {
  Scene scene = preset_scene("paper");
  CylinderPlot cylinder;
  cylinder.pellet = 0;
  scene.figure = FigureSpec{{cylinder}, 1024, 1024};
  if (!cylinder_panels_available()) {
    state.SkipWithError("this build draws no 3-D panels");
    return;
  }
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const RenderResult warm = render_figure(scene.figure, scene.model,
                                          simulate(scene.model, plan.options), ImageFormat::png);
  if (!warm.ok()) {
    state.SkipWithError(warm.error->message.c_str());
    return;
  }
  run_scene(state, scene, ImageFormat::png);
}
BENCHMARK(BM_Cylinder1024Png)->Unit(benchmark::kMillisecond);

// The paper scene's run, as the figure asks for it, with each method at the preset's tolerances.
void BM_PaperSimulateMethod(benchmark::State& state, Method method) {
  Scene scene = preset_scene("paper");
  scene.sim.method = method;
  run_scene(state, scene, std::nullopt);
}
BENCHMARK_CAPTURE(BM_PaperSimulateMethod, dopri5, Method::dopri5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaperSimulateMethod, dop853, Method::dop853)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaperSimulateMethod, radau5, Method::radau5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaperSimulateMethod, auto, Method::automatic) -> Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vibro::bench

BENCHMARK_MAIN();
