// Work-precision: for each method and tolerance, what a run costs (median wall time) and how
// accurate it truly is. The true error is measured against what is exact where it applies (the
// first integral of unforced paper-law motion; the energy without friction and forcing), and
// otherwise against a reference run at the tightest tolerance with another method.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/integrators/stepper.h"
#include "core/model/model.h"
#include "core/run/sim_options.h"

namespace vibro {

enum class ErrorReference {
  first_integral,  // max residual of the exact first integral (unforced, paper law, friction)
  energy,          // max energy drift (no friction, no forcing)
  reference_run,   // event times and final states against a tight run of another method
};
std::string_view error_reference_name(ErrorReference r);

struct WorkPrecisionOptions {
  std::vector<Method> methods = {Method::dopri5, Method::dop853, Method::radau5, Method::taylor,
                                 Method::automatic};
  std::vector<double> rtols = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  double atol_per_rtol = 1e-2;  // atol = rtol · this
  int repeats = 3;              // runs per point; the time is their median
  // Wall clock for the whole measurement, ms: each run gets at most what is left of it (and at
  // most its own deadline_ms); the points not reached by then are left out and said.
  double deadline_ms = std::numeric_limits<double>::infinity();
};

struct WorkPrecisionPoint {
  Method method = Method::automatic;
  double rtol = 0.0, atol = 0.0;
  double median_ms = 0.0;
  // Dimensionless: residual or drift relative to the energy scale, or (reference run) the
  // largest of |Δt|/sqrt(R/g) over the events, |Δφ| and sqrt(R/g)·|Δφ̇| at the end; when the
  // event sequences part ways, over the events they share (events_match is then false).
  double error = 0.0;
  double estimate = 0.0;  // the run's own stats.error_estimate, to compare with `error`
  long steps = 0, rhs_evals = 0;
  long events = 0;
  bool events_match = true;  // reference run: the same events in the same order
  bool completed = true;
};

struct WorkPrecisionReport {
  ErrorReference reference = ErrorReference::reference_run;
  std::string reference_description;
  std::vector<WorkPrecisionPoint> points;  // by method, then by decreasing rtol
  std::string message;                     // why points are missing, if they are
};

// Which exact reference applies to a model.
ErrorReference error_reference_for(const Model& model);

WorkPrecisionReport work_precision(const Model& model, const SimOptions& base,
                                   const WorkPrecisionOptions& options = {});

}  // namespace vibro
