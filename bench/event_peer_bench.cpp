// Peers with their own event location (bench/peers/forced_pellet_peer.h) against vibro on one
// forced pellet between two limiters for 1000 s: do they find the same impacts (count, and
// times against vibro's dop853 at rtol 1e-13), and how long do they take.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "run_error.h"
#include "solvers.h"
#if defined(VIBRO_BENCH_ODEINT) || defined(VIBRO_BENCH_CVODE)
#include "peers/forced_pellet_peer.h"
#endif

namespace vibro::bench {
namespace {

constexpr double kEnd = 1000.0;
constexpr int kCompared = 50;

std::vector<double> limiter_impacts(const RunResult& run) {
  std::vector<double> t;
  for (const Event& e : run.events)
    if (e.kind == EventKind::limiter) t.push_back(e.t);
  return t;
}

const std::vector<double>& reference_impacts() {
  static const std::vector<double> t = [] {
    const Scene scene = forced_pellet_scene(kEnd);
    return limiter_impacts(reference_run(scene.model, unrecorded(scene)));
  }();
  return t;
}

void report(benchmark::State& state, const std::vector<double>& impacts, long steps, long rhs) {
  const std::vector<double>& ref = reference_impacts();
  double first = 0.0, all = 0.0;
  for (std::size_t i = 0; i < std::min(impacts.size(), ref.size()); ++i) {
    const double d = std::abs(impacts[i] - ref[i]);
    if (i < kCompared) first = std::max(first, d);
    all = std::max(all, d);
  }
  state.counters["impacts"] = static_cast<double>(impacts.size());
  state.counters["reference_impacts"] = static_cast<double>(ref.size());
  state.counters["event_time_error"] = first;  // the first 50 impacts, s
  state.counters["all_impacts_error"] = all;   // every impact, s
  state.counters["same_impacts"] = impacts.size() == ref.size() ? 1.0 : 0.0;
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["rhs_evals"] = static_cast<double>(rhs);
}

void vibro_run(benchmark::State& state, double rtol) {
  const Scene scene = forced_pellet_scene(kEnd);
  SimOptions options = unrecorded(scene);
  options.rtol = rtol;
  options.atol = rtol * 1e-2;
  options.check = false;  // the peers run once, without a shadow run
  RunResult run;
  for (auto _ : state) {
    run = simulate(scene.model, options);
    benchmark::DoNotOptimize(run);
  }
  report(state, limiter_impacts(run), run.stats.steps, run.stats.rhs_evals);
}

#if defined(VIBRO_BENCH_ODEINT) || defined(VIBRO_BENCH_CVODE)
template <class Run>
void peer_run(benchmark::State& state, Run&& run_peer) {
  PeerRun run;
  for (auto _ : state) {
    run = run_peer();
    benchmark::DoNotOptimize(run);
  }
  if (!run.failure.empty()) {
    state.SkipWithError(run.failure.c_str());
    return;
  }
  report(state, run.impact_times, run.steps, run.rhs_evals);
}
#endif

}  // namespace
}  // namespace vibro::bench

int main(int argc, char** argv) {
  using namespace vibro::bench;
  benchmark::Initialize(&argc, argv);
  static const vibro::Model model = forced_pellet_scene(kEnd).model;
  for (double rtol : {1e-6, 1e-8, 1e-10}) {
    char tol[16];
    std::snprintf(tol, sizeof tol, "rtol:%.0e", rtol);
    auto name = [&](const char* solver) { return std::string("EventPeers/") + solver + "/" + tol; };
    benchmark::RegisterBenchmark(name("vibro-auto").c_str(), [rtol](benchmark::State& s) {
      vibro_run(s, rtol);
    })->Unit(benchmark::kMillisecond);
#ifdef VIBRO_BENCH_ODEINT
    benchmark::RegisterBenchmark(name("odeint-dopri5").c_str(), [rtol](benchmark::State& s) {
      peer_run(s, [&] { return odeint_forced_pellet(model, kEnd, rtol, rtol * 1e-2); });
    })->Unit(benchmark::kMillisecond);
#endif
#ifdef VIBRO_BENCH_CVODE
    for (bool bdf : {false, true}) {
      benchmark::RegisterBenchmark(
          name(bdf ? "cvode-bdf" : "cvode-adams").c_str(),
          [rtol, bdf](benchmark::State& s) {
            peer_run(s, [&] { return cvode_forced_pellet(model, kEnd, rtol, rtol * 1e-2, bdf); });
          })
          ->Unit(benchmark::kMillisecond);
    }
#endif
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
