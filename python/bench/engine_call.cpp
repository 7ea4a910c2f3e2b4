// The engine called from C++, for python/bench/overhead.py: a preset read once, then
// simulate(model, options) as `vibro simulate` calls it, REPEATS times; prints the median CPU
// time of one call in ms (this thread's: on a shared machine, wall time measures the others).
// What vibro.simulate costs beyond it is the Python call's overhead.
// A run's result is freed within its own timing, as the Python call's timing holds the freeing
// of the run it replaces.
// Usage: python_engine_call PRESET [REPEATS]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "core/analysis/checked_run.h"
#include "io/presets.h"
#include "io/scene_json.h"

// This thread's CPU time, ms.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const auto text = vibro::preset_json(argv[1]);
  if (!text) return 2;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 200;
  const auto read = vibro::scene_from_text(*text);
  const vibro::Scene& scene = std::get<vibro::Scene>(read);
  vibro::SimOptions options = scene.sim;
  options.record.assign(scene.model.size(), scene.trajectories);
  vibro::simulate(scene.model, options);  // warm, as the Python side is
  std::vector<double> ms;
  for (int k = 0; k < repeats; ++k) {
    const double start = cpu_ms();
    {
      const vibro::RunResult run = vibro::simulate(scene.model, options);
    }  // freed inside the timing: a Python caller frees its last run inside its next call's
    ms.push_back(cpu_ms() - start);
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  std::printf("%.4f\n", ms[ms.size() / 2]);
  return 0;
}
