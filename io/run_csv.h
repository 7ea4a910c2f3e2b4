// A run's events or its sampled trajectory as CSV with a header row (API.md, "Exports"), for a
// spreadsheet or pandas: `POST /api/simulate?format=csv[&what=trajectory]`,
// `vibro simulate -o run.csv [--what trajectory]`.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/run/result.h"
#include "core/run/validate.h"

namespace vibro {

// uniform: the state of every pellet at t = 0, dt, 2·dt, ... (a run with SimOptions::stops set
// by uniform_times), for an FFT or a comparison with a measured signal.
enum class RunTable { events, trajectory, uniform };

// "events" or "trajectory"; nothing for another name.
std::optional<RunTable> run_table_named(std::string_view name);

// An event's rows in the events table: one per pellet it touches, its `member`-th (from 0) that
// pellet's; one for an event that touches none (then its pellet and speeds are empty cells).
// Each event's rows in turn, in the events' order, are what run_csv writes and the Python
// module's `Run.events` holds.
inline std::size_t event_row_count(const Event& event) {
  return std::max<std::size_t>(event.pellets.size(), 1);
}

// events: event,t,kind,pellet,limiter,phi,dphi_before,dphi_after, one value per cell: a row for
// each pellet an event touches (a collision has two, a stuck body's impact one per member), its
// speeds before and after, the rows of one event sharing its index `event` (from 0), t, kind,
// limiter (−1 where none) and phi;
// trajectory: t,pellet,branch,phi,dphi, one row per sample of the recorded branches.
// uniform: t,pellet,phi,dphi, one row per pellet at each of the run's stops.
// Numbers to 17 significant digits: they read back as the same doubles.
std::string run_csv(const RunResult& run, RunTable table);

// The samples a uniform trajectory may hold in all (times × pellets): about 100 bytes each while
// the run keeps them.
inline constexpr long kMaxUniformSamples = 1'000'000;

// The times 0, dt, 2·dt, ... up to t_end, where a run sampled at a uniform dt keeps its state
// (SimOptions::stops: its steps land on them, so each is a step's end, not an interpolation).
// Refused naming `field`: a dt that is not a positive finite number, or that makes more than
// `most` samples for `pellets` pellets.
std::variant<std::vector<double>, FieldError> uniform_times(double dt, double t_end, int pellets,
                                                            long most, const std::string& field);

}  // namespace vibro
