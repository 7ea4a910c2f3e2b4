// What a step costs beyond its right-hand sides: a run's time over (rhs_evals × one bare
// evaluation of the same segment dynamics). report.py divides the medians; the multiple is the
// cost of the step arithmetic, the dense output, the event search and the event instants.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "core/model/dynamics.h"
#include "core/model/motion.h"

namespace vibro::bench {
namespace {

// Every pellet its own body, sliding the way it starts: the system of the run's first segment.
std::vector<Body> sliding_bodies(const Model& model) {
  std::vector<Body> bodies;
  for (int i = 0; i < model.size(); ++i) {
    Body b;
    b.members = {i};
    b.s = model.pellets[i].dphi0 < 0.0 ? -1 : 1;
    bodies.push_back(b);
  }
  return bodies;
}

void bare_rhs(benchmark::State& state, const Scene& scene) {
  const std::vector<Body> bodies = sliding_bodies(scene.model);
  Vec y(3 * scene.model.size()), dydt(y.size());
  for (int i = 0; i < scene.model.size(); ++i) {
    y[phi_index(i)] = scene.model.pellets[i].phi0;
    y[dphi_index(i)] = scene.model.pellets[i].dphi0;
    y[work_index(i)] = 0.0;
  }
  const SegmentDynamics sys(scene.model, bodies, y);
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(y.data());
    sys.rhs(t, y, dydt);
    benchmark::DoNotOptimize(dydt.data());
    t += 1e-6;  // a new t each time, so nothing is hoisted out of the loop
  }
}

void run(benchmark::State& state, const Scene& scene, Method method) {
  SimOptions options = unrecorded(scene);
  options.method = method;
  options.check = false;  // the step's cost alone: the trust check's shadow run is trust_bench's
  long rhs = 0, steps = 0;
  for (auto _ : state) {
    RunResult r = simulate(scene.model, options);
    rhs = r.stats.rhs_evals;
    steps = r.stats.steps;
    benchmark::DoNotOptimize(r);
  }
  state.counters["rhs_evals"] = static_cast<double>(rhs);
  state.counters["steps"] = static_cast<double>(steps);
}

void BM_BareRhs_paper(benchmark::State& state) { bare_rhs(state, preset_scene("paper")); }
BENCHMARK(BM_BareRhs_paper);
void BM_BareRhs_forced(benchmark::State& state) { bare_rhs(state, forced_pellet_scene(100.0)); }
BENCHMARK(BM_BareRhs_forced);

void BM_Run_paper(benchmark::State& state, Method method) {
  run(state, preset_scene("paper"), method);
}
void BM_Run_forced(benchmark::State& state, Method method) {
  run(state, forced_pellet_scene(100.0), method);
}
BENCHMARK_CAPTURE(BM_Run_paper, dopri5, Method::dopri5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_paper, dop853, Method::dop853)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_paper, radau5, Method::radau5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_paper, auto, Method::automatic) -> Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_forced, dopri5, Method::dopri5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_forced, dop853, Method::dop853)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_forced, radau5, Method::radau5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run_forced, auto, Method::automatic) -> Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vibro::bench

BENCHMARK_MAIN();
