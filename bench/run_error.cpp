#include "run_error.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/analysis/checked_run.h"

namespace vibro::bench {
namespace {

std::vector<const Event*> impacts_of(const RunResult& run) {
  std::vector<const Event*> out;
  for (const Event& e : run.events) {
    if (e.kind == EventKind::limiter || e.kind == EventKind::collision ||
        e.kind == EventKind::chatter) {
      out.push_back(&e);
    }
  }
  return out;
}

}  // namespace

RunResult reference_run(const Model& model, const SimOptions& options) {
  SimOptions o = options;
  o.method = Method::dop853;
  o.rtol = 1e-13;
  o.atol = 1e-15;
  o.record.assign(model.size(), false);
  return simulate(model, o);
}

RunError run_error(const Model& model, const RunResult& run, const RunResult& reference,
                   int max_compared) {
  RunError e;
  const std::vector<const Event*> got = impacts_of(run), want = impacts_of(reference);
  e.impacts = static_cast<int>(got.size());
  e.compared = std::min<int>(max_compared, static_cast<int>(want.size()));
  for (int i = 0; i < e.compared; ++i) {
    if (i >= static_cast<int>(got.size()) || got[i]->kind != want[i]->kind ||
        got[i]->pellets != want[i]->pellets || got[i]->limiter != want[i]->limiter) {
      e.same_impacts = false;
      break;
    }
    e.event_time_error = std::max(e.event_time_error, std::abs(got[i]->t - want[i]->t));
  }
  const double time_scale = std::sqrt(model.R / model.g);
  for (std::size_t i = 0; i < reference.summary.final.size() && i < run.summary.final.size(); ++i) {
    const FinalState &a = run.summary.final[i], &b = reference.summary.final[i];
    e.final_error =
        std::max({e.final_error, std::abs(a.phi - b.phi), std::abs(a.dphi - b.dphi) * time_scale});
  }
  e.error = e.same_impacts ? std::max(e.event_time_error, e.final_error) : 1.0;
  return e;
}

}  // namespace vibro::bench
