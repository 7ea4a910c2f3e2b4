#include "io/work_precision_json.h"

#include <cmath>

namespace vibro {

nlohmann::json work_precision_to_json(const WorkPrecisionReport& report) {
  auto num = [](double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  nlohmann::json rows = nlohmann::json::array();
  for (const WorkPrecisionPoint& p : report.points) {
    rows.push_back({{"method", method_name(p.method)},
                    {"rtol", p.rtol},
                    {"atol", p.atol},
                    {"median_ms", num(p.median_ms)},
                    {"error", num(p.error)},
                    {"estimate", num(p.estimate)},
                    {"steps", p.steps},
                    {"rhs_evals", p.rhs_evals},
                    {"events", p.events},
                    {"events_match", p.events_match},
                    {"completed", p.completed}});
  }
  nlohmann::json out = {{"error_reference", error_reference_name(report.reference)},
                        {"reference", report.reference_description},
                        {"points", rows}};
  if (!report.message.empty()) out["message"] = report.message;
  return out;
}

}  // namespace vibro
