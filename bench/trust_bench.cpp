// What the trust check costs: every preset simulated as its scene asks (nothing recorded), with
// the check (the default) and without it. report.py prints the ratio of the medians.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "io/presets.h"

namespace vibro::bench {
namespace {

void run_preset(benchmark::State& state, const std::string& name, bool check) {
  const Scene scene = preset_scene(name.c_str());
  SimOptions options = unrecorded(scene);
  options.check = check;
  long events = 0;
  for (auto _ : state) {
    RunResult run = simulate(scene.model, options);
    events = static_cast<long>(run.events.size());
    benchmark::DoNotOptimize(run);
  }
  state.counters["events"] = static_cast<double>(events);
}

}  // namespace
}  // namespace vibro::bench

int main(int argc, char** argv) {
  for (const vibro::PresetText& p : vibro::presets()) {
    const std::string name(p.name);
    for (bool check : {false, true}) {
      benchmark::RegisterBenchmark(
          ("Trust/" + name + (check ? "/checked" : "/unchecked")).c_str(),
          [name, check](benchmark::State& s) { vibro::bench::run_preset(s, name, check); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
