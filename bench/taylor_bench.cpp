// The Taylor method against DOP853 (issue 33): steps and time per run on the impact-oscillator
// and paper presets at rtol 1e-10 and 1e-12 (atol = rtol/100, no trust check, nothing recorded),
// and the impact oscillator's 1,000-value sweep on one thread at those tolerances
// (sweep_bench's spec: 50 periods of transient, 20 recorded).
// Names: Taylor/<preset>/<method>/rtol:<r> and TaylorSweep/<method>/rtol:<r>.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "core/analysis/sweep.h"
#include "timed_run.h"

namespace vibro::bench {
namespace {

constexpr const char* kPresets[] = {"impact-oscillator", "paper"};
constexpr Method kMethods[] = {Method::dop853, Method::taylor};
constexpr double kRtols[] = {1e-10, 1e-12};

std::string label(Method method, double rtol) {
  char r[32];
  std::snprintf(r, sizeof r, "%g", rtol);
  return std::string(method_name(method)) + "/rtol:" + r;
}

SimOptions options_for(const Scene& scene, Method method, double rtol) {
  SimOptions o = unrecorded(scene);
  o.method = method;
  o.rtol = rtol;
  o.atol = rtol / 100;
  o.check = false;
  return o;
}

void sweep(benchmark::State& state, const Scene& scene, const SimOptions& options) {
  SweepSpec spec = *scene.sweep;
  spec.axis.count = 1000;
  spec.continuation = Continuation::none;
  spec.transient = 50;
  spec.record = 20;
  SweepControl control;
  control.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(run_sweep(scene.model, options, spec, control));
  state.counters["runs_per_s"] = benchmark::Counter(
      1000.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Registered from main: the presets are parsed from tables that static initialisers fill.
void register_benchmarks() {
  for (const char* name : kPresets) {
    const Scene scene = preset_scene(name);
    for (Method method : kMethods)
      for (double rtol : kRtols) {
        const SimOptions o = options_for(scene, method, rtol);
        const std::string id = std::string("Taylor/") + name + "/" + label(method, rtol);
        benchmark::RegisterBenchmark(id.c_str(), [scene, o](benchmark::State& s) {
          run_counting_steps(s, scene, o);
        })->Unit(benchmark::kMillisecond);
      }
  }
  const Scene oscillator = preset_scene("impact-oscillator");
  for (Method method : kMethods)
    for (double rtol : kRtols) {
      const SimOptions o = options_for(oscillator, method, rtol);
      const std::string id = "TaylorSweep/" + label(method, rtol);
      benchmark::RegisterBenchmark(
          id.c_str(), [oscillator, o](benchmark::State& s) { sweep(s, oscillator, o); })
          ->Unit(benchmark::kSecond)
          ->UseRealTime()
          ->Iterations(3);
    }
}

}  // namespace
}  // namespace vibro::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  vibro::bench::register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
