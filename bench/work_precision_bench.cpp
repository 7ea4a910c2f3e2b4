// Work-precision: each integrator (vibro's and the peers behind vibro's Stepper interface)
// runs the same scene through vibro's driver at rtol 1e-4 … 1e-12 (atol = rtol/100), so every
// run searches the same events the same way and only the integrator differs. Each benchmark
// reports its run time and, as counters, its true error against a dop853 run at rtol 1e-13
// (run_error.h). report.py compares times at matched error.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "run_error.h"
#include "solvers.h"

namespace vibro::bench {
namespace {

struct Case {
  std::string name;  // "paper", "forced"
  Scene scene;
  SimOptions options;
  RunResult reference;
};

void work_precision(benchmark::State& state, const Case& c, const Solver& solver, double rtol) {
  SimOptions options = c.options;
  options.rtol = rtol;
  options.atol = rtol * 1e-2;
  const StepperOptions stepper_options{options.rtol, options.atol,
                                       std::numeric_limits<double>::infinity()};
  RunResult run;
  for (auto _ : state) {
    run = simulate(c.scene.model, options, solver.make(stepper_options));
    benchmark::DoNotOptimize(run);
  }
  if (run.stats.termination != Termination::completed) {
    state.SkipWithError(run.stats.message.c_str());
    return;
  }
  const RunError e = run_error(c.scene.model, run, c.reference);
  state.counters["error"] = e.error;
  state.counters["event_time_error"] = e.event_time_error;
  state.counters["final_error"] = e.final_error;
  state.counters["impacts"] = e.impacts;
  state.counters["reference_impacts"] = run_error(c.scene.model, c.reference, c.reference).impacts;
  state.counters["compared"] = e.compared;
  state.counters["same_impacts"] = e.same_impacts ? 1.0 : 0.0;
  state.counters["steps"] = static_cast<double>(run.stats.steps);
  state.counters["rhs_evals"] = static_cast<double>(run.stats.rhs_evals);
}

}  // namespace
}  // namespace vibro::bench

int main(int argc, char** argv) {
  using namespace vibro;
  using namespace vibro::bench;
  benchmark::Initialize(&argc, argv);
  // Cases and solvers live until the benchmarks have run.
  static std::vector<Case> cases;
  const Scene paper = preset_scene("paper");
  cases.push_back({"paper", paper, unrecorded(paper), {}});
  const Scene forced = forced_pellet_scene(1000.0);
  cases.push_back({"forced", forced, unrecorded(forced), {}});
  for (Case& c : cases) c.reference = reference_run(c.scene.model, c.options);
  static const std::vector<Solver> list = solvers();
  for (const Case& c : cases) {
    for (const Solver& s : list) {
      for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
        char name[96];
        std::snprintf(name, sizeof name, "WorkPrecision/%s/%s/rtol:%.0e", c.name.c_str(),
                      s.name.c_str(), rtol);
        benchmark::RegisterBenchmark(name, [&c, &s, rtol](benchmark::State& st) {
          work_precision(st, c, s, rtol);
        })->Unit(benchmark::kMillisecond);
      }
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
