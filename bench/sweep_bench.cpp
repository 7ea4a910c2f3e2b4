// Sweep throughput (issue 10): a 1,000-value sweep of the impact oscillator over Ω (50 periods
// of transient, 20 recorded, the trust check off as a researcher's script runs), on 1 and on 2
// threads: runs and section points per second, and the scaling between them.
#include <benchmark/benchmark.h>

#include "bench_scenes.h"
#include "core/analysis/sweep.h"

namespace vibro::bench {
namespace {

void BM_SweepImpactOscillator(benchmark::State& state) {
  const Scene scene = preset_scene("impact-oscillator");
  SweepSpec spec = *scene.sweep;
  spec.axis.count = 1000;
  spec.continuation = Continuation::none;
  spec.transient = 50;
  spec.record = 20;
  SimOptions options = scene.sim;
  options.check = false;
  SweepControl control;
  control.threads = static_cast<int>(state.range(0));
  long points = 0;
  for (auto _ : state) {
    const SweepResult r = run_sweep(scene.model, options, spec, control);
    points = 0;
    for (const SweepRun& run : r.runs) points += static_cast<long>(run.points.size());
    benchmark::DoNotOptimize(points);
  }
  state.counters["runs_per_s"] = benchmark::Counter(
      1000.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["points_per_s"] =
      benchmark::Counter(static_cast<double>(points) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SweepImpactOscillator)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
}  // namespace vibro::bench

BENCHMARK_MAIN();
