// Results read back from the JSON they were saved as, so that `vibro plot` redraws them without
// running anything: a sweep's points and runs as write_sweep_result_json writes them, and a
// periodic motion's continued branch as orbit_result_json writes it. Columns or keys this reader
// does not draw from are passed over (a newer writer may add some); those it needs are checked
// for type and length, and a failure names the field ("points.t", "branch[3].multipliers").
#pragma once

#include <nlohmann/json.hpp>
#include <variant>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/sweep.h"
#include "core/run/validate.h"

namespace vibro {

// The runs, each with its section points. What JSON cannot hold comes back as it was written:
// a non-finite coordinate (null) as NaN, a Lyapunov exponent of −infinity (null) as none.
std::variant<SweepResult, FieldError> read_sweep_result(const nlohmann::json& json);

// The branch, its bifurcations, whether it reached its end and why not. The JSON says `stable`
// only: a point not stable reads back neutral where its multipliers are (neutral_within the band
// its stability was decided to, multiplier_band of the options of the scene that made it).
std::variant<OrbitBranch, FieldError> read_orbit_branch(const nlohmann::json& json,
                                                        double multiplier_band);

}  // namespace vibro
