// What a sweep job may cost on this server beyond its simulated time (which the sweep's spec
// checks itself, core/analysis/sweep.h, validate_sweep): the section points it keeps and its wall
// clock, refused up front where they can be known, and the share of the wall clock each of its runs
// gets.
#pragma once

#include <optional>

#include "io/scene.h"
#include "server/api_error.h"
#include "server/config.h"

namespace vibro::server {

// The least wall clock a sweep's run may be left, ms: below it a run of any length ends by its
// deadline, and the sweep would be its deadlines' noise.
inline constexpr double kMinSweepRunMs = 10.0;

// Refuses (400, naming the field) a stroboscopic sweep whose points, runs × (record + 1) ×
// pellets, exceed limits.sweep_points ("sweep.record"), and a sweep whose runs, those made one
// after another on `threads` threads, would each be left less than kMinSweepRunMs of
// limits.sweep_seconds ("sweep.count"). An impact section's points are known only as it runs:
// the job stops at the limit.
std::optional<ApiError> check_sweep_cost(const Scene& scene, const Limits& limits, int threads);

// The deadline of each run of the sweep, ms: the server's deadline of one simulation, or the
// run's share of limits.sweep_seconds (nine tenths of it over the runs made one after another)
// when that is shorter, so that a sweep of runs that all reach their deadline still ends within
// its budget.
double sweep_run_deadline_ms(const SweepSpec& spec, const Limits& limits, int threads);

}  // namespace vibro::server
