// A run's events or its sampled trajectory as CSV with a header row (API.md, "Exports"), for a
// spreadsheet or pandas: `POST /api/simulate?format=csv[&what=trajectory]`,
// `vibro simulate -o run.csv [--what trajectory]`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/run/result.h"

namespace vibro {

enum class RunTable { events, trajectory };

// "events" or "trajectory"; nothing for another name.
std::optional<RunTable> run_table_named(std::string_view name);

// events: event,t,kind,pellet,limiter,phi,dphi_before,dphi_after, one value per cell: a row for
// each pellet an event touches (a collision has two, a stuck body's impact one per member), its
// speeds before and after, the rows of one event sharing its index `event` (from 0), t, kind,
// limiter (−1 where none) and phi;
// trajectory: t,pellet,branch,phi,dphi, one row per sample of the recorded branches.
// Numbers to 17 significant digits: they read back as the same doubles.
std::string run_csv(const RunResult& run, RunTable table);

}  // namespace vibro
