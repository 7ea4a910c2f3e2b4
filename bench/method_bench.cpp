// Each method on every simulation preset at rtol 1e-6, 1e-9 and 1e-12 (atol = rtol/100, no
// trust check, nothing recorded): is `auto` within 1.2× of the fastest single method everywhere?
// Names: Method/<preset>/<method>/rtol:<r>.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "timed_run.h"

namespace vibro::bench {
namespace {

constexpr const char* kPresets[] = {"paper",        "chatter",        "frictionless-elastic",
                                    "grazing",      "high-frequency", "impact-oscillator",
                                    "loop",         "mass-ratio",     "plastic-limiter",
                                    "rest-in-cone", "stiff-friction", "tiny-radius"};
constexpr Method kMethods[] = {Method::dopri5, Method::dop853, Method::radau5, Method::automatic};
constexpr double kRtols[] = {1e-6, 1e-9, 1e-12};

// Registered from main: the presets are parsed from tables that static initialisers fill.
void register_benchmarks() {
  for (const char* name : kPresets) {
    const Scene scene = preset_scene(name);
    for (Method method : kMethods)
      for (double rtol : kRtols) {
        SimOptions o = unrecorded(scene);
        o.method = method;
        o.rtol = rtol;
        o.atol = rtol / 100;
        o.check = false;
        char label[32];
        std::snprintf(label, sizeof label, "%g", rtol);
        const std::string id = std::string("Method/") + name + "/" +
                               std::string(method_name(method)) + "/rtol:" + label;
        benchmark::RegisterBenchmark(id.c_str(), [scene, o](benchmark::State& s) {
          run_counting_steps(s, scene, o);
        })->Unit(benchmark::kMillisecond);
      }
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
