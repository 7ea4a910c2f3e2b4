#include "core/analysis/work_precision.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/analysis/checked_run.h"
#include "core/run/deadline.h"

namespace vibro {
namespace {

bool unforced(const Model& model) {
  return std::none_of(model.pellets.begin(), model.pellets.end(),
                      [](const Pellet& p) { return p.force.active(); });
}

bool same_event(const Event& a, const Event& b) {
  return a.kind == b.kind && a.pellets == b.pellets && a.limiter == b.limiter;
}

// Error of a run against the reference (see WorkPrecisionPoint::error).
double reference_error(const Model& model, const RunResult& run, const RunResult& ref,
                       bool& match) {
  const double T = time_scale(model);
  const std::size_t n = std::min(run.events.size(), ref.events.size());
  double error = 0.0;
  match = run.events.size() == ref.events.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (!same_event(run.events[k], ref.events[k])) {
      match = false;
      if (k == 0) return 1.0;
      break;
    }
    error = std::max(error, std::abs(run.events[k].t - ref.events[k].t) / T);
  }
  if (!match) return n == 0 ? 1.0 : error;  // the runs went different ways: their common part
  for (std::size_t i = 0; i < run.summary.final.size(); ++i) {
    const FinalState& a = run.summary.final[i];
    const FinalState& b = ref.summary.final[i];
    error = std::max({error, std::abs(a.phi - b.phi), T * std::abs(a.dphi - b.dphi)});
  }
  return error;
}

}  // namespace

std::string_view error_reference_name(ErrorReference r) {
  switch (r) {
    case ErrorReference::first_integral:
      return "first_integral";
    case ErrorReference::energy:
      return "energy";
    case ErrorReference::reference_run:
      return "reference_run";
  }
  return "?";
}

ErrorReference error_reference_for(const Model& model) {
  if (!unforced(model)) return ErrorReference::reference_run;
  if (model.alpha0 == 0.0) return ErrorReference::energy;
  if (model.friction == FrictionLaw::paper && !model.damped())
    return ErrorReference::first_integral;
  return ErrorReference::reference_run;
}

namespace {

// The runs that errors are measured against, at the tightest tolerance, with another method than
// the one measured (dop853's own against dopri5's).
struct ReferenceRuns {
  RunResult dop853, dopri5;
  const RunResult& for_method(Method m) const { return m == Method::dop853 ? dopri5 : dop853; }
};

ReferenceRuns reference_runs(const Model& model, SimOptions o, const Deadline& deadline,
                             double own_deadline_ms) {
  ReferenceRuns refs;
  o.rtol = 1e-13;
  o.atol = 1e-15;
  o.method = Method::dop853;
  o.deadline_ms = std::min(own_deadline_ms, deadline.left_ms());
  refs.dop853 = simulate(model, o);
  o.method = Method::dopri5;
  o.deadline_ms = std::min(own_deadline_ms, deadline.left_ms());
  refs.dopri5 = simulate(model, o);
  return refs;
}

// One point: the median of `repeats` runs' times (as many as the deadline lets start), the last
// run's error against the report's reference.
WorkPrecisionPoint measure(const Model& model, SimOptions o, const WorkPrecisionOptions& options,
                           const Deadline& deadline, ErrorReference reference,
                           const ReferenceRuns& refs) {
  const double own_deadline_ms = o.deadline_ms;
  auto within = [&] { return std::min(own_deadline_ms, deadline.left_ms()); };
  std::vector<double> times;
  RunResult run;
  for (int r = 0; r < std::max(options.repeats, 1) && (r == 0 || within() > 0.0); ++r) {
    o.deadline_ms = within();
    run = simulate(model, o);
    times.push_back(run.stats.wall_ms);
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  WorkPrecisionPoint p;
  p.method = o.method;
  p.rtol = o.rtol;
  p.atol = o.atol;
  p.median_ms = times[times.size() / 2];
  p.estimate = run.stats.error_estimate;
  p.steps = run.stats.steps;
  p.rhs_evals = run.stats.rhs_evals;
  p.events = static_cast<long>(run.events.size());
  p.completed = run.stats.termination == Termination::completed;
  switch (reference) {
    case ErrorReference::first_integral:
      p.error = run.stats.first_integral_residual;
      break;
    case ErrorReference::energy:
      p.error = run.stats.energy_defect;
      break;
    case ErrorReference::reference_run:
      p.error = reference_error(model, run, refs.for_method(o.method), p.events_match);
      break;
  }
  return p;
}

}  // namespace

WorkPrecisionReport work_precision(const Model& model, const SimOptions& base,
                                   const WorkPrecisionOptions& options) {
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  WorkPrecisionReport report;
  report.reference = error_reference_for(model);
  SimOptions o = base;
  o.record.assign(model.size(), false);
  o.check = false;  // each method's own work; its trust check is measured apart (ACCURACY.md)
  ReferenceRuns refs;
  if (report.reference == ErrorReference::reference_run) {
    refs = reference_runs(model, o, deadline, base.deadline_ms);
    report.reference_description = "dop853 at rtol 1e-13 (dopri5 at rtol 1e-13 for dop853 itself)";
  } else {
    report.reference_description = report.reference == ErrorReference::energy
                                       ? "the exact energy (no friction, no forcing)"
                                       : "the exact first integral (unforced, paper law)";
  }
  const std::size_t asked = options.methods.size() * options.rtols.size();
  for (Method method : options.methods) {
    for (double rtol : options.rtols) {
      if (std::min(base.deadline_ms, deadline.left_ms()) <= 0.0) {
        report.message = "measured " + std::to_string(report.points.size()) + " of " +
                         std::to_string(asked) + " points: the rest would pass the deadline of " +
                         std::to_string(static_cast<long>(options.deadline_ms)) + " ms";
        return report;
      }
      o.method = method;
      o.rtol = rtol;
      o.atol = rtol * options.atol_per_rtol;
      o.deadline_ms = base.deadline_ms;
      report.points.push_back(measure(model, o, options, deadline, report.reference, refs));
    }
  }
  return report;
}

}  // namespace vibro
