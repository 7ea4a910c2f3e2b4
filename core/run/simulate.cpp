#include "core/run/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <utility>

#include "core/analysis/lyapunov.h"
#include "core/analysis/trust.h"
#include "core/events/contacts.h"
#include "core/events/crossing_finder.h"
#include "core/events/event_tolerances.h"
#include "core/events/instant.h"
#include "core/events/interval.h"
#include "core/events/watch.h"
#include "core/run/energy_balance.h"
#include "core/run/recorder.h"
#include "core/run/summary.h"

namespace vibro {
namespace {

using Clock = std::chrono::steady_clock;

EventTolerances exact_speeds(EventTolerances tol) {
  tol.v_eps = 0.0;
  return tol;
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

// The driver: integrate a motion interval step by step, search each step's dense output for the
// interval's events, resolve the instant of the earliest, open the next interval.
class Simulation {
 public:
  Simulation(const Model& model, const SimOptions& options, std::unique_ptr<Stepper> stepper)
      : model_(model),
        opt_(options),
        tol_(event_tolerances(model)),
        start_tol_(exact_speeds(tol_)),
        law_(model),
        y_(initial_state(model)),
        armed_(model.limiters.size(), true),
        neighbours_(model.size() >= 2 ? circular_neighbours(y_, model.size())
                                      : std::vector<Neighbours>{}),
        energy_(model, y_),
        recorder_(model, options.record, options.record_until, options.max_samples),
        stepper_(stepper ? std::move(stepper)
                         : make_stepper(options.method, StepperOptions{options.rtol, options.atol,
                                                                       options.longest_step_scale *
                                                                           longest_step(model),
                                                                       options.auto_explicit})),
        times_(std::max(options.samples_per_step, 2) + 1),
        states_(times_.size(), Vec(y_.size())) {}

  RunResult run();

 private:
  // `at_start`: the instant at t = 0, where the speeds are the scene's own.
  std::vector<Body> instant(double t, const std::vector<Body>& before,
                            const InstantContacts& contacts, bool at_start = false);
  double step_limit() const;
  void keep_stops(double t, const std::vector<Body>& bodies);
  void open_interval(double t, std::vector<Body> bodies);
  // Integrates the open interval until its first event (true) or t_end or a stop (false).
  bool integrate_to_event(double& t, std::vector<Crossing>& found);
  void polish(const Crossing& c, double a, double b, double& t);
  void record_inside(double a, double b, double t_event, bool searched_inside);
  bool over_budget(double t);
  void fail(double t, Termination why, const std::string& message);

  const Model& model_;
  const SimOptions& opt_;
  const EventTolerances tol_;
  // At the start the speeds are given, not computed: none is round-off to snap to rest (a pellet
  // started at 50 rad/s on a circle of 1e-300 m, where v_eps is 3e137 rad/s, was put at rest).
  const EventTolerances start_tol_;
  const SlidingLaw law_;  // for the rates of the watches of the motion, when polishing a root
  Vec y_;
  std::vector<bool> armed_;
  const std::vector<Neighbours> neighbours_;
  std::optional<MotionInterval> interval_;
  CrossingFinder finder_;
  EnergyBalance energy_;
  Recorder recorder_;
  std::unique_ptr<Stepper> stepper_;
  std::vector<double> times_;  // the samples of each step's dense output: times and states
  std::vector<Vec> states_;
  Vec scratch_;        // states and rates while polishing a root
  Vec midpoint_rate_;  // the rate that moves the state to a polished root
  Vec unsnapped_;      // the state before an instant's snap
  std::vector<Event> events_;
  Stats stats_;
  double max_fi_residual_ = 0.0;
  int same_instant_ = 0;
  double last_instant_ = -1.0;
  Clock::time_point started_ = Clock::now();
  bool stopped_ = false;
  std::size_t next_stop_ = 0;  // into opt_.stops
  std::vector<StateAt> stops_;
  // The first instant whose impacts' order was decided below the tolerance: the trust ends there.
  std::optional<Graze> unordered_;
  // opt_.keep_path: the segments that end after opt_.keep_events_from (a sweep's record), up to
  // opt_.path_limit of them.
  std::vector<PathSegment> path_;
  bool path_full_ = false;
  bool keeps_path() const { return opt_.keep_path && !path_full_; }
  bool smooth_ = false;  // the last instant was one of reversals alone
};

std::vector<double> to_vector(const Vec& y) { return {y.data(), y.data() + y.size()}; }

// An instant of reversals alone leaves the state as it was and every body sliding: the stepper
// goes on with its step size (Stepper::continue_smoothly).
bool only_reversals(const std::vector<Event>& events) {
  return !events.empty() && std::all_of(events.begin(), events.end(), [](const Event& e) {
    return e.kind == EventKind::reversal;
  });
}

// The time the next step may not pass: the run's end, or the next stop.
double Simulation::step_limit() const {
  return next_stop_ < opt_.stops.size() ? std::min(opt_.t_end, opt_.stops[next_stop_]) : opt_.t_end;
}

// Keeps the state at every stop up to t, where the state is y_ and these are the bodies.
void Simulation::keep_stops(double t, const std::vector<Body>& bodies) {
  for (; next_stop_ < opt_.stops.size() && opt_.stops[next_stop_] <= t; ++next_stop_)
    stops_.push_back({opt_.stops[next_stop_], final_states(model_, bodies, y_)});
}

void Simulation::fail(double t, Termination why, const std::string& message) {
  std::ostringstream msg;
  msg << "stopped at t = " << t << " s: " << message;
  stats_.termination = why;
  stats_.message = msg.str();
  stopped_ = true;
}

bool Simulation::over_budget(double t) {
  const StepperStats& s = stepper_->stats();
  if (static_cast<long>(events_.size()) >= opt_.max_events) {
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
  }
  return stopped_;
}

// Resolves an instant at t and keeps what it reports; returns the next interval's bodies.
std::vector<Body> Simulation::instant(double t, const std::vector<Body>& before,
                                      const InstantContacts& contacts, bool at_start) {
  if (keeps_path()) {
    if (!path_.empty()) {
      path_.back().t_end = t;
      if (t < opt_.keep_events_from) path_.pop_back();
    }
    path_full_ = path_.size() >= opt_.path_limit;
    if (!path_full_) path_.push_back({t, before, to_vector(y_), {}, {}, {}, {}, t});
  }
  InstantOutcome out =
      resolve_instant(model_, at_start ? start_tol_ : tol_, t, before, contacts, y_, armed_);
  smooth_ = only_reversals(out.events);
  if (out.unordered >= 0 && !unordered_)
    unordered_ = Graze{.of = Graze::Of::order, .pellet = out.unordered, .t = t, .earliest = t};
  if (keeps_path()) {
    path_.back().events = out.events;
    path_.back().bodies = out.bodies;
    path_.back().y = to_vector(y_);
  }
  for (Event& e : out.events) {
    // A chatter that accumulates after the run's end is listed at the end; its t_accumulation
    // says when it would come to rest.
    e.t = std::min(e.t, opt_.t_end);
    if (e.t >= opt_.keep_events_from) events_.push_back(std::move(e));
  }
  for (int i = 0; i < model_.size(); ++i)
    if (out.touched[i]) recorder_.end_branch(i);
  energy_.add_instant(out.kinetic_change);
  energy_.check(y_);
  return std::move(out.bodies);
}

void Simulation::open_interval(double t, std::vector<Body> bodies) {
  interval_.emplace(model_, std::move(bodies), armed_, neighbours_, t, y_, tol_);
  if (smooth_)
    stepper_->continue_smoothly(interval_->dynamics(), t, y_);
  else
    stepper_->start(interval_->dynamics(), t, y_);
  finder_.start(interval_->watches(), model_, interval_->bodies(), t, y_, opt_.rtol, opt_.atol);
  recorder_.sample(t, y_);
  recorder_.check_normal_force(t, y_, interval_->bodies());
  if (keeps_path()) {
    PathSegment& p = path_.back();
    p.bodies = interval_->bodies();
    p.normal_sides.clear();
    for (std::size_t b = 0; b < p.bodies.size(); ++b)
      p.normal_sides.push_back(interval_->dynamics().normal_side(static_cast<int>(b)));
  }
}

// A root found on a dense output of lower order than the steps (every method's) errs by that
// order. One step to the root of the watch's quadratic at the precise state brings the time to
// the steps' accuracy, and the state moves to it by the midpoint rule: both then err by the
// correction's cube, unless the watch turns within ten corrections (a pellet that turns back at
// the limiter), where the dense root stands. Without it, DOP853 took a pellet's flights between
// a limiter and its turns one step each at every tolerance, and its dense output put each turn
// 1.3e-13 s late, a run and its shadow alike (trust scan, seed 10, scene 71).
//
// The rate and curvature are the watch's own at the precise state where the state gives them (a
// watch of the motion), else differences on the dense output over a thousandth of the way from
// the step's start, where a deflated watch starts. Over a thousandth of the step, flights of
// 1.4e-6 s inside steps of 3 ms took their slope from the watch before its start, 15 % off;
// with a straight line, the correction was refused wherever the watch's slope changed by a
// thousandth over it. DOP853 put the 10,000th bounce of an elastic pair 4e-7 s late at every
// tolerance down to 1e-8, its shadow alike, and Radau IIA at rtol 1e-6 listed 3,711 of its
// 10,080 events (trust scan, seed 11, scene 259; tests/core/polish_test.cpp).
void Simulation::polish(const Crossing& c, double a, double b, double& t) {
  const Watch& w = interval_->watches()[c.watch];
  const std::vector<Body>& bodies = interval_->bodies();
  Vec& y = scratch_;
  double value = 0.0, slope = 0.0, curvature = 0.0;
  if (follows_motion(w.kind)) {
    stepper_->precise_state(t, y);
    const Closing at = closing(w, model_, law_, bodies, t, y, /*with_curvature=*/true);
    value = at.value;
    slope = at.rate;
    curvature = at.curvature;
  } else {
    auto g_dense = [&](double tt) {
      stepper_->dense(tt, y);
      return evaluate(w, model_, bodies, tt, y);
    };
    const double delta = 1e-3 * (t - a);
    const double before = g_dense(t - delta), at = g_dense(t), after = g_dense(t + delta);
    slope = (after - before) / (2.0 * delta);
    curvature = (after - 2.0 * at + before) / (delta * delta);
    stepper_->precise_state(t, y);
    value = evaluate(w, model_, bodies, t, y);
  }
  // The root nearest t of the quadratic (a straight line for a speed, whose curvature the state
  // does not give).
  const double disc = slope * slope - 2.0 * curvature * value;
  if (!(disc >= 0.0)) return;
  const double dt = -2.0 * value / (slope + std::copysign(std::sqrt(disc), slope));
  if (!std::isfinite(dt) || std::abs(curvature * dt) > 0.1 * std::abs(slope)) return;
  if (!(t + dt >= a && t + dt <= b)) return;  // the root lies in this step: no correction leaves it
  const SegmentDynamics& f = interval_->dynamics();
  y_ = y;
  f.rhs(t, y_, y);
  y = y_ + 0.5 * dt * y;
  midpoint_rate_.resize(y_.size());
  f.rhs(t + 0.5 * dt, y, midpoint_rate_);
  y_ += dt * midpoint_rate_;
  t += dt;
}

// The recorded curves of the step (a, b] before the event at t_event, if any (its own state is
// sampled once its instant is placed), in as many pieces as keep each chord close to its arc:
// the event search's samples (times_, states_, computed here if the search skipped them), or
// more. y_ is the state at a.
void Simulation::record_inside(double a, double b, double t_event, bool searched_inside) {
  const int m = static_cast<int>(times_.size()) - 1;
  if (!searched_inside)
    for (int k = 0; k < m; ++k) stepper_->dense(times_[k], states_[k]);
  const int near_middle = (m - 1) / 2;
  const double theta = (times_[near_middle] - a) / (b - a);
  const int n = recorder_.pieces(y_, states_[near_middle], theta, states_[m], m + 1);
  if (n == m + 1) {
    for (int k = 0; k <= m && times_[k] < t_event; ++k) recorder_.sample(times_[k], states_[k]);
    return;
  }
  Vec& y = scratch_;
  y.resize(y_.size());
  for (int k = 1; k <= n; ++k) {
    const double t = k == n ? b : a + (b - a) * k / n;
    if (!(t < t_event)) break;
    if (k < n) stepper_->dense(t, y);
    recorder_.sample(t, k < n ? y : states_[m]);
  }
}

bool Simulation::integrate_to_event(double& t, std::vector<Crossing>& found) {
  const int m = static_cast<int>(times_.size()) - 1;
  std::vector<double>& times = times_;
  std::vector<Vec>& states = states_;
  const MotionInterval& interval = *interval_;
  while (!stopped_ && t < opt_.t_end) {
    const StepStatus status = stepper_->step(step_limit());
    if (status != StepStatus::ok) {
      t = stepper_->t();
      fail(t, Termination::numerical_failure,
           status == StepStatus::step_underflow ? "the step size underflowed"
           : status == StepStatus::non_finite   ? "the state became non-finite"
                                                : "the implicit method's Newton iteration failed");
      return false;
    }
    const double a = stepper_->t_prev(), b = stepper_->t();
    times[m] = b;
    states[m] = stepper_->y();
    // Samples inside the step for the watches near their roots; a step where every watch stays
    // far from zero is searched at its end alone.
    const bool calm = !opt_.sample_every_step &&
                      finder_.calm(interval.watches(), model_, interval.bodies(), a, b, states[m]);
    const int first = calm ? m : 0;
    for (int k = 0; k < m; ++k) times[k] = a + (b - a) * (k + 1) / (m + 1);
    for (int k = first; k < m; ++k) stepper_->dense(times[k], states[k]);
    const auto sampled_times = std::span<const double>(times).subspan(first);
    const auto sampled_states = std::span<const Vec>(states).subspan(first);
    found = finder_.find(interval.watches(), model_, interval.bodies(), *stepper_, sampled_times,
                         sampled_states, tol_.simultaneous(b));
    const double t_stop = found.empty() ? b : found.front().t;
    if (recorder_.wants_samples(a))
      record_inside(a, b, found.empty() ? std::numeric_limits<double>::infinity() : t_stop,
                    first == 0);
    if (found.empty()) {
      t = b;
      y_ = stepper_->y();
    } else {
      t = t_stop;
      stepper_->dense(t, y_);
      polish(found.front(), a, b, t);
      max_fi_residual_ = std::max(max_fi_residual_, interval.first_integral_residual(y_));
      recorder_.sample(t, y_);
    }
    recorder_.check_normal_force(t, y_, interval.bodies());
    if (found.empty()) keep_stops(t, interval.bodies());
    if (!std::isfinite(y_.sum())) {
      fail(t, Termination::numerical_failure, "the state became non-finite");
      return false;
    }
    if (!found.empty()) return true;
    if (over_budget(t)) return false;
  }
  return false;
}

RunResult Simulation::run() {
  const auto t0 = Clock::now();
  double t = 0.0;
  const InstantContacts start = initial_contacts(model_, tol_, y_);
  std::vector<Body> bodies = instant(0.0, initial_bodies(model_, y_), start, true);
  keep_stops(0.0, bodies);
  std::vector<Crossing> found;
  while (!stopped_ && t < opt_.t_end) {
    open_interval(t, std::exchange(bodies, {}));
    if (interval_->at_rest_for_good()) {
      t = opt_.t_end;
      keep_stops(t, interval_->bodies());
      break;
    }
    if (!integrate_to_event(t, found)) break;
    same_instant_ = std::abs(t - last_instant_) <= tol_.simultaneous(t) ? same_instant_ + 1 : 0;
    last_instant_ = t;
    if (same_instant_ > tol_.max_same_instant) {
      fail(t, Termination::numerical_failure,
           "events do not advance in time (an unresolved Zeno sequence)");
      break;
    }
    unsnapped_ = y_;
    const InstantContacts contacts = snap(model_, tol_, *interval_, found, neighbours_, armed_, y_);
    energy_.add_snap(unsnapped_, y_);
    bodies = instant(t, interval_->bodies(), contacts);
    if (!stopped_) keep_stops(t, bodies);
    if (!stopped_) over_budget(t);
  }
  if (!stopped_) {
    t = std::max(t, opt_.t_end);
    if (interval_)
      max_fi_residual_ = std::max(max_fi_residual_, interval_->first_integral_residual(y_));
    energy_.check(y_);
  } else if (!std::isfinite(y_.sum())) {
    y_ = stepper_->y();  // the last finite state
  }
  RunResult result;
  recorder_.sample(std::min(t, opt_.t_end), y_);
  recorder_.finish(t, result);
  std::stable_sort(events_.begin(), events_.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });
  result.summary = summarize(model_, events_);
  // The bodies of the last instant, or of the interval that ran to the end.
  result.summary.final = final_states(model_, bodies.empty() ? interval_->bodies() : bodies, y_);
  const bool at_rest = bodies.empty() && interval_->at_rest_for_good();
  result.summary.ends_vibro_impact = ends_vibro_impact(
      events_, std::min(t, opt_.t_end), stats_.termination == Termination::completed, at_rest);
  result.events = std::move(events_);
  result.stops = std::move(stops_);
  result.graze = finder_.first_graze();
  if (unordered_ && (!result.graze || unordered_->earliest < result.graze->earliest))
    result.graze = unordered_;
  if (!path_.empty() && !path_full_) path_.back().t_end = std::min(t, opt_.t_end);
  result.path = std::move(path_);

  const StepperStats& s = stepper_->stats();
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
  st.energy_defect = energy_.max_defect();
  st.first_integral_residual = max_fi_residual_;
  st.error_estimate = std::max(st.energy_defect, st.first_integral_residual);
  st.t_reached = std::min(t, opt_.t_end);
  st.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return result;
}

// The options the simulation runs with: the path kept where the exponents need it.
SimOptions with_path(const SimOptions& options) {
  SimOptions o = options;
  o.keep_path = options.keep_path || options.lyapunov;
  return o;
}

// The exponents from the path, which is then dropped unless it was asked for.
void add_lyapunov(const Model& model, const SimOptions& options, RunResult& run) {
  if (!options.lyapunov) return;
  run.lyapunov =
      lyapunov_spectrum(model, run.path, options.rtol, std::max(0.0, options.keep_events_from));
  if (!options.keep_path) run.path.clear();
}

}  // namespace

RunResult simulate(const Model& model, const SimOptions& options) {
  const SimOptions o = with_path(options);
  RunResult run = Simulation(model, o, nullptr).run();
  add_lyapunov(model, options, run);
  if (!options.check) {
    apply_unchecked(model, run);
    return run;
  }
  SimOptions shadow = check_options(options);
  shadow.deadline_ms = options.deadline_ms - run.stats.wall_ms;  // one deadline for both
  const Model perturbed = check_model(model);
  const RunResult checked = Simulation(perturbed, shadow, nullptr).run();
  apply_check(model, checked, run, shadow.deadline_ms - checked.stats.wall_ms);
  return run;
}

RunResult simulate(const Model& model, const SimOptions& options,
                   std::unique_ptr<Stepper> stepper) {
  const SimOptions o = with_path(options);
  RunResult run = Simulation(model, o, std::move(stepper)).run();
  add_lyapunov(model, options, run);
  apply_unchecked(model, run);
  return run;
}

}  // namespace vibro
