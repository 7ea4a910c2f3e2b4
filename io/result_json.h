// A run as JSON, in the shape of API.md. Non-finite numbers never reach the output.
#pragma once

#include <nlohmann/json.hpp>

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro {

nlohmann::json result_to_json(const RunResult& run, const Model& model);

// The parts of a run's JSON that other results carry too (a periodic orbit's events and the
// stats of its check run): one event of "events", and "stats" without its event count.
nlohmann::json event_to_json(const Event& event);
nlohmann::json stats_to_json(const Stats& stats);

// A number, or null where it is not finite: JSON has no NaN or Inf.
nlohmann::json finite_number(double x);

// One sentence that answers the paper's question: after how many impacts the system stops
// being vibro-impact, and where the pellets end.
std::string answer_sentence(const RunResult& run, const Model& model);

}  // namespace vibro
