#include "core/run/run_state.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/model/dynamics.h"
#include "core/run/simulate.h"

namespace vibro {
namespace {

EventTolerances exact_speeds(EventTolerances tol) {
  tol.v_eps = 0.0;
  return tol;
}

std::vector<bool> initially_armed(const Model& model) {
  std::vector<bool> armed;
  for (const Limiter& l : model.limiters) armed.push_back(!l.mobile || l.armed);
  return armed;
}

Vec initial_state(const Model& model) {
  Vec y(3 * model.size());
  for (int i = 0; i < model.size(); ++i) {
    y[phi_index(i)] = model.pellets[i].phi0;
    y[dphi_index(i)] = model.pellets[i].dphi0;
    y[work_index(i)] = 0.0;
  }
  return y;
}

// An instant of reversals alone leaves the state as it was and every body sliding: the stepper
// goes on with its step size (Stepper::continue_smoothly).
bool only_reversals(const EventList& events) {
  return !events.empty() && std::all_of(events.begin(), events.end(), [](const Event& e) {
    return e.kind == EventKind::reversal;
  });
}

}  // namespace

RunState::RunState(const Model& model, const SolverOptions& options, Stepper& stepper,
                   std::span<RunObserver* const> observers)
    : model_(model),
      opt_(options),
      tol_(event_tolerances(model)),
      start_tol_(exact_speeds(tol_)),
      stepper_(stepper),
      observers_(observers),
      y_(initial_state(model)),
      armed_(initially_armed(model)),
      neighbours_(model.size() >= 2 ? circular_neighbours(y_, model.size())
                                    : std::vector<Neighbours>{}),
      times_(std::max(options.samples_per_step, 2) + 1),
      states_(times_.size(), Vec(y_.size())) {
  for (RunObserver* o : observers) {
    const RunObserver::PerStep takes = o->per_step();
    if (takes.landing) landing_.push_back(o);
    if (takes.step) on_step_.push_back(o);
    if (takes.step_end) on_step_end_.push_back(o);
    if (takes.settled) on_settled_.push_back(o);
  }
}

bool RunState::step_failed(double& t, StepStatus status) {
  t = stepper_.t();
  fail(t, Termination::numerical_failure,
       status == StepStatus::step_underflow ? "the step size underflowed"
       : status == StepStatus::non_finite   ? "the state became non-finite"
                                            : "the implicit method's Newton iteration failed");
  return false;
}

void RunState::note_instant(double t, const InstantOutcome& out) {
  smooth_ = only_reversals(out.events);
  if (out.unordered >= 0 && !unordered_)
    unordered_ = Graze{.of = Graze::Of::order, .pellet = out.unordered, .t = t, .earliest = t};
  for (const Event& e : out.events)
    if (std::min(e.t, opt_.t_end) >= opt_.keep_events_from) ++events_;
}

bool RunState::advances(double t) {
  same_instant_ = std::abs(t - last_instant_) <= tol_.simultaneous(t) ? same_instant_ + 1 : 0;
  last_instant_ = t;
  if (same_instant_ <= tol_.max_same_instant) return true;
  fail(t, Termination::numerical_failure,
       "events do not advance in time (an unresolved Zeno sequence)");
  return false;
}

void RunState::fail(double t, Termination why, const std::string& message) {
  std::ostringstream msg;
  msg << "stopped at t = " << t << " s: " << message;
  stats_.termination = why;
  stats_.message = msg.str();
  stopped_ = true;
}

bool RunState::over_budget(double t) {
  const StepperStats& s = stepper_.stats();
  if (events_ >= opt_.max_events) {
    fail(t, Termination::event_limit,
         "the run reached its limit of " + std::to_string(opt_.max_events) + " events");
  } else if (s.steps + s.rejected >= opt_.max_steps) {
    fail(t, Termination::step_limit,
         "the run reached its limit of " + std::to_string(opt_.max_steps) + " steps");
  } else if (std::isfinite(opt_.deadline_ms) &&
             std::chrono::duration<double, std::milli>(Clock::now() - started_).count() >
                 opt_.deadline_ms) {
    std::ostringstream why;
    why << "the run took longer than its deadline of " << opt_.deadline_ms << " ms";
    fail(t, Termination::deadline, why.str());
  } else if (opt_.cancelled && ++since_cancel_poll_ >= kCancelPollSteps) {
    since_cancel_poll_ = 0;
    if (opt_.cancelled()) fail(t, Termination::cancelled, "the run was cancelled");
  }
  return stopped_;
}

RunResult RunState::finish(const EndView& end, const std::optional<Graze>& graze) {
  RunResult result;
  result.graze = graze;
  if (unordered_ && (!result.graze || unordered_->earliest < result.graze->earliest))
    result.graze = unordered_;
  const StepperStats& s = stepper_.stats();
  Stats& st = result.stats;
  st = std::move(stats_);
  st.method = std::string(method_name(opt_.method));
  st.rtol = opt_.rtol;
  st.atol = opt_.atol;
  st.steps = s.steps;
  st.rejected = s.rejected;
  st.rhs_evals = s.rhs_evals;
  st.jac_evals = s.jac_evals;
  st.lu_decomps = s.lu_decomps;
  st.stiff_switches = s.stiff_switches;
  st.dopri5_steps = s.dopri5_steps;
  st.dop853_steps = s.dop853_steps;
  st.taylor_steps = s.taylor_steps;
  st.t_reached = end.t_reached;
  for (RunObserver* o : observers_) o->on_end(end, result);
  result.summary.armed = armed_;
  st.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - started_).count();
  return result;
}

std::unique_ptr<Stepper> make_stepper(const Model& model, const SolverOptions& options,
                                      AutoExplicit auto_explicit, double longest_step_scale) {
  return make_stepper(options.method,
                      StepperOptions{options.rtol, options.atol,
                                     longest_step_scale * longest_step(model), auto_explicit});
}

}  // namespace vibro
