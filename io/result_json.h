// A run as JSON, in the shape of API.md. Non-finite numbers never reach the output.
#pragma once

#include <nlohmann/json.hpp>

#include "core/model.h"
#include "core/result.h"

namespace vibro {

nlohmann::json result_to_json(const RunResult& run, const Model& model);

// One sentence that answers the paper's question: after how many impacts the system stops
// being vibro-impact, and where the pellets end.
std::string answer_sentence(const RunResult& run, const Model& model);

}  // namespace vibro
