#include "core/run/observers.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/run/section_period.h"
#include "core/run/summary.h"

namespace vibro {
namespace {

std::vector<double> to_vector(const Vec& y) { return {y.data(), y.data() + y.size()}; }

}  // namespace

void Recording::on_instant(const InstantView& instant) {
  for (std::size_t i = 0; i < instant.touched.size(); ++i)
    if (instant.touched[i]) recorder_.end_branch(static_cast<int>(i));
}

void Recording::on_interval(double t, const Vec& y, const MotionInterval& interval) {
  recorder_.sample(t, y);
  recorder_.check_normal_force(t, y, interval.bodies());
}

// The recorded curves of the step (a, b] before its event, if any (its own state is sampled at
// on_step_end), in as many pieces as keep each chord close to its arc: the event search's
// samples (computed here where the search skipped them), or more. The step is kept for
// on_step_end, where the normal force's sign change is located on its dense output.
void Recording::on_step(const StepSamples& s) {
  step_ = &s.stepper;
  if (!recorder_.wants_samples(s.a)) return;
  const int m = static_cast<int>(s.times.size()) - 1;
  states_.resize(s.times.size());
  for (int k = 0; k < s.first_searched && k < m; ++k) {
    states_[k].resize(s.y_a.size());
    s.stepper.dense(s.times[k], states_[k]);
  }
  auto state = [&](int k) -> const Vec& {
    return k >= s.first_searched ? s.states[k] : states_[k];
  };
  const int near_middle = (m - 1) / 2;
  const double theta = (s.times[near_middle] - s.a) / (s.b - s.a);
  const int n = recorder_.pieces(s.y_a, state(near_middle), theta, state(m), m + 1);
  if (n == m + 1) {
    for (int k = 0; k <= m && s.times[k] < s.t_event; ++k) recorder_.sample(s.times[k], state(k));
    return;
  }
  scratch_.resize(s.y_a.size());
  for (int k = 1; k <= n; ++k) {
    const double t = k == n ? s.b : s.a + (s.b - s.a) * k / n;
    if (!(t < s.t_event)) break;
    if (k < n) s.stepper.dense(t, scratch_);
    recorder_.sample(t, k < n ? scratch_ : state(m));
  }
}

void Recording::on_step_end(double t, const Vec& y, const MotionInterval& interval, bool at_event) {
  if (at_event) recorder_.sample(t, y);
  recorder_.check_normal_force(t, y, interval.bodies(), step_);
}

void Recording::on_end(const EndView& end, RunResult& result) {
  recorder_.sample(end.t_reached, end.y);
  recorder_.finish(end.t, result);
}

double SectionStops::landing() const {
  return next_ < times_.size() ? times_[next_] : std::numeric_limits<double>::infinity();
}

void SectionStops::on_settled(double t, const Vec& y, const std::vector<Body>& bodies) {
  const std::size_t before = kept_.size();
  for (; next_ < times_.size() && times_[next_] <= t; ++next_)
    kept_.push_back({times_[next_], final_states(model_, bodies, y)});
  if (window_ == 0 || kept_.size() == before || kept_.size() < window_) return;
  const std::span<const StateAt> last(kept_.end() - static_cast<std::ptrdiff_t>(window_),
                                      kept_.end());
  settled_ = section_settled(last, speed_scale(model_));
}

void SectionStops::on_end(const EndView& end, RunResult& result) {
  result.stops = std::move(kept_);
  result.settled = settled_ && end.ended;
}

// A segment opens at each instant with the state that reached it; the instant's outcome and the
// interval's bodies complete it, and the next instant closes it. Segments that end before `from`
// are dropped.
void PathKeeper::on_instant(const InstantView& in) {
  if (full_) return;
  if (!path_.empty()) {
    path_.back().t_end = in.t;
    if (in.t < from_) path_.pop_back();
  }
  full_ = path_.size() >= limit_;
  if (!full_)
    path_.push_back({in.t,
                     in.bodies_before,
                     to_vector(in.y_before),
                     {in.events.begin(), in.events.end()},
                     in.bodies_after,
                     {},
                     to_vector(in.y_after),
                     in.t});
}

void PathKeeper::on_interval(double, const Vec&, const MotionInterval& interval) {
  if (full_) return;
  PathSegment& p = path_.back();
  p.bodies = interval.bodies();
  p.normal_sides.clear();
  for (std::size_t b = 0; b < p.bodies.size(); ++b)
    p.normal_sides.push_back(interval.dynamics().normal_side(static_cast<int>(b)));
}

void PathKeeper::on_end(const EndView& end, RunResult& result) {
  if (!path_.empty() && !full_) path_.back().t_end = std::min(end.t, t_end_);
  result.path = std::move(path_);
}

void EventLog::on_instant(const InstantView& instant) {
  for (const Event& e : instant.events) {
    // A chatter that accumulates after the run's end is listed at the end; its t_accumulation
    // says when it would come to rest.
    const double t = std::min(e.t, t_end_);
    if (t < from_) continue;
    events_.push_back(e);
    events_.back().t = t;
  }
}

void EventLog::on_end(const EndView& end, RunResult& result) {
  std::stable_sort(events_.begin(), events_.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });
  result.summary = summarize(model_, events_);
  result.summary.final = final_states(model_, end.bodies, end.y);
  result.summary.ends_vibro_impact =
      ends_vibro_impact(events_, end.t_reached, !end.stopped, end.at_rest_for_good);
  result.events = std::move(events_);
}

void EnergyCheck::on_instant(const InstantView& instant) {
  if (instant.unsnapped) balance_->add_snap(*instant.unsnapped, instant.y_before);
  balance_->add_instant(instant.kinetic_change);
  balance_->check(instant.y_after);
}

void EnergyCheck::on_step_end(double, const Vec& y, const MotionInterval& interval, bool at_event) {
  if (at_event) max_fi_residual_ = std::max(max_fi_residual_, interval.first_integral_residual(y));
}

void EnergyCheck::on_end(const EndView& end, RunResult& result) {
  if (!end.stopped) {
    if (end.interval)
      max_fi_residual_ = std::max(max_fi_residual_, end.interval->first_integral_residual(end.y));
    balance_->check(end.y);
  }
  Stats& st = result.stats;
  st.energy_defect = balance_->max_defect();
  st.first_integral_residual = max_fi_residual_;
  st.error_estimate = std::max(st.energy_defect, st.first_integral_residual);
}

StandardOutputs::StandardOutputs(const Model& model, const SimOptions& options)
    : events_(model, options.t_end, options.keep_events_from),
      energy_(model),
      recording_(model, options.record, options.record_until, options.max_samples) {
  list_ = {&events_, &energy_, &recording_};
  if (!options.stops.empty())
    list_.push_back(&stops_.emplace(model, options.stops, options.settle_window));
  if (options.keep_path)
    list_.push_back(&path_.emplace(options.t_end, options.keep_events_from, options.path_limit));
}

}  // namespace vibro
