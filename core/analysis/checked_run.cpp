#include "core/analysis/checked_run.h"

#include <algorithm>

#include "core/analysis/lyapunov.h"
#include "core/analysis/trust.h"
#include "core/run/observers.h"

namespace vibro {
namespace {

// The options the run goes with: the path kept where the exponents need it.
SimOptions with_path(const SimOptions& options) {
  SimOptions o = options;
  o.keep_path = options.keep_path || options.lyapunov;
  return o;
}

// The run with the outputs the options ask for, and its exponents (the path then dropped unless
// it was asked for).
RunResult run_with_outputs(const Model& model, const SimOptions& options, Stepper& stepper) {
  const SimOptions o = with_path(options);
  StandardOutputs outputs(model, o);
  RunResult run = simulate(model, static_cast<const SolverOptions&>(o), stepper, outputs.list());
  if (!options.lyapunov) return run;
  run.lyapunov =
      lyapunov_spectrum(model, run.path, options.rtol, std::max(0.0, options.keep_events_from));
  if (!options.keep_path) run.path.clear();
  return run;
}

}  // namespace

RunResult simulate(const Model& model, const SimOptions& options) {
  RunResult run = run_with_outputs(model, options, *make_stepper(model, options));
  if (!options.check || run.stats.termination == Termination::cancelled) {
    apply_unchecked(model, run);
    return run;
  }
  const double deadline_ms = options.deadline_ms - run.stats.wall_ms;  // one deadline for both
  // A run that ended where its section settled is checked over the time it ran.
  SimOptions shadow_of = options;
  if (run.settled) shadow_of.t_end = run.stats.t_reached;
  const RunResult checked = run_shadow(model, shadow_of, deadline_ms);
  apply_check(model, checked, run, deadline_ms - checked.stats.wall_ms);
  return run;
}

RunResult run_shadow(const Model& model, const SimOptions& options, double deadline_ms) {
  ShadowOptions shadow = check_options(options);
  shadow.options.deadline_ms = deadline_ms;
  const Model moved = check_model(model);
  return run_with_outputs(
      moved, shadow.options,
      *make_stepper(moved, shadow.options, shadow.auto_explicit, shadow.longest_step_scale));
}

RunResult simulate(const Model& model, const SimOptions& options,
                   std::unique_ptr<Stepper> stepper) {
  if (!stepper) stepper = make_stepper(model, options);
  RunResult run = run_with_outputs(model, options, *stepper);
  apply_unchecked(model, run);
  return run;
}

}  // namespace vibro
