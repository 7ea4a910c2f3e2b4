// One scene simulated per benchmark iteration, its step count reported as the counter "steps";
// a run that does not complete ends the benchmark with its message.
#pragma once

#include <benchmark/benchmark.h>

#include "core/analysis/checked_run.h"
#include "io/scene.h"

namespace vibro::bench {

inline void run_counting_steps(benchmark::State& state, const Scene& scene,
                               const SimOptions& options) {
  long steps = 0;
  for (auto _ : state) {
    const RunResult r = simulate(scene.model, options);
    if (r.stats.termination != Termination::completed) {
      state.SkipWithError(r.stats.message.c_str());
      return;
    }
    steps = r.stats.steps;
    benchmark::DoNotOptimize(r);
  }
  state.counters["steps"] = static_cast<double>(steps);
}

}  // namespace vibro::bench
