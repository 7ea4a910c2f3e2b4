// A work-precision report as JSON: one row per method and tolerance.
#pragma once

#include <nlohmann/json.hpp>

#include "core/analysis/work_precision.h"

namespace vibro {

nlohmann::json work_precision_to_json(const WorkPrecisionReport& report);

}  // namespace vibro
